// The laws of bodies on static meshes, over generated scenes and OBJ files: a flat floor made of
// many triangles is a plane (nothing snags on its seams), a ball rolls in a bowl with the period
// of the bowl's sphere, and nothing dropped on a bumpy ground gains energy.
#include "tests/physics/generated_scenes.h"

#include <array>
#include <numbers>
#include <sstream>

namespace impulse::demos::laws {
namespace {

// Writes an OBJ file beside the laws' scenes, named by its text, and returns its name (the scene's
// file names it from its own folder).
std::string obj_file(const std::string& text) {
  uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : text) hash = (hash ^ uint8_t(c)) * 0x100000001b3ull;
  const fs::path directory = fs::path(testing::TempDir()) / "impulse-laws";
  fs::create_directories(directory);
  const fs::path path = directory / ("mesh-" + std::to_string(hash) + ".obj");
  if (!fs::exists(path)) std::ofstream(path) << text;
  return path.filename().string();
}

// OBJ text of vertices and triangles (counter-clockwise from the front).
std::string obj_text(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& triangles) {
  std::ostringstream text;
  text.precision(17);
  for (const Vec3& v : vertices) text << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : triangles) text << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return text.str();
}

// A square grid of `cells` x `cells` over [-half, half] in x-z at y = height(x, z), each cell cut
// along a drawn diagonal, the inner corners moved within the floor by up to a third of a cell:
// triangles of every shape and size, facing up.
std::string ground_obj(Draw& draw, double half, int cells, const std::function<double(double, double)>& height) {
  std::vector<Vec3> vertices;
  const double cell = 2 * half / cells;
  for (int i = 0; i <= cells; ++i)
    for (int j = 0; j <= cells; ++j) {
      double x = -half + i * cell, z = -half + j * cell;
      const bool inner = i > 0 && i < cells && j > 0 && j < cells;
      const double dx = draw.uniform(-cell / 3, cell / 3);
      const double dz = draw.uniform(-cell / 3, cell / 3);
      if (inner) x += dx, z += dz;
      vertices.emplace_back(x, height(x, z), z);
    }
  std::vector<std::array<int, 3>> triangles;
  auto at = [&](int i, int j) { return i * (cells + 1) + j; };
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      // Seen from above (+y), x right and z down the page: a, d, c, b turn counter-clockwise.
      if (draw.coin())
        triangles.push_back({a, d, c}), triangles.push_back({a, c, b});
      else
        triangles.push_back({a, d, b}), triangles.push_back({d, c, b});
    }
  return obj_text(vertices, triangles);
}

// The inside of a sphere of `radius` about the origin, from its bottom up to `rim_angle` from it:
// `rings` rings of `segments` triangles, facing the centre.
std::string bowl_obj(double radius, double rim_angle, int rings, int segments) {
  std::vector<Vec3> vertices{Vec3(0, -radius, 0)};
  for (int ring = 1; ring <= rings; ++ring) {
    const double polar = rim_angle * ring / rings;  // from the bottom
    for (int s = 0; s < segments; ++s) {
      const double around = 2 * std::numbers::pi * s / segments;
      vertices.emplace_back(radius * std::sin(polar) * std::cos(around), -radius * std::cos(polar), radius * std::sin(polar) * std::sin(around));
    }
  }
  std::vector<std::array<int, 3>> triangles;
  auto at = [&](int ring, int s) { return ring == 0 ? 0 : 1 + (ring - 1) * segments + (s % segments); };
  auto facing_centre = [&](std::array<int, 3> t) {
    const Vec3 n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    if (n.dot(-vertices[t[0]]) < 0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  };
  for (int s = 0; s < segments; ++s) facing_centre({0, at(1, s), at(1, s + 1)});
  for (int ring = 1; ring < rings; ++ring)
    for (int s = 0; s < segments; ++s) {
      facing_centre({at(ring, s), at(ring + 1, s), at(ring + 1, s + 1)});
      facing_centre({at(ring, s), at(ring + 1, s + 1), at(ring, s + 1)});
    }
  return obj_text(vertices, triangles);
}

// A body of a drawn shape and size, lying on y = 0 at the origin (its lowest point there): its
// table's shape lines, and its half height.
std::string lying_body(Draw& draw, double& half_height) {
  const int kind = draw.integer(0, 5);
  const double size = draw.uniform(0.1, 0.6);
  const auto n = [](double value) { return SceneText::number(value); };
  switch (kind) {
    case 0: half_height = size; return "shape = \"sphere\"\nradius = " + n(size) + "\n";
    case 1: {
      const Vec3 s = draw.vector(0.1, 0.8);
      half_height = s.y() / 2;
      return "shape = \"box\"\nsize = " + SceneText::vector(s) + "\n";
    }
    case 2: half_height = size / 2; return "shape = \"capsule\"\nradius = " + n(size / 2) + "\nheight = " + n(size * 2) + "\nrotation = [90, 0, 0]\n";
    case 3: half_height = size / 2; return "shape = \"cylinder\"\nradius = " + n(size) + "\nheight = " + n(size) + "\n";
    case 4: half_height = size / 2; return "shape = \"cylinder\"\nradius = " + n(size / 2) + "\nheight = " + n(size * 2) + "\nrotation = [90, 0, 0]\n";
    default: {
      const int sides = draw.integer(3, 8);
      half_height = size / 2;
      return "shape = \"prism\"\nsides = " + std::to_string(sides) + "\nradius = " + n(size) + "\nheight = " + n(size) + "\n";
    }
  }
}

// A body sliding without friction over a flat floor of drawn triangles, in a drawn direction.
std::string sliding(Draw& draw) {
  const int cells = draw.integer(4, 24);
  const std::string floor = obj_file(ground_obj(draw, 8, cells, [](double, double) { return 0.0; }));
  double half_height = 0;
  const std::string body = lying_body(draw, half_height);
  const double heading = draw.uniform(0, 2 * std::numbers::pi);
  const double speed = draw.uniform(0.5, 3);
  SceneText scene("a body sliding over a flat mesh", 2);
  scene.line("[world]\nsleeping = false");
  scene.line("[[body]]\nname = \"floor\"\nshape = \"mesh\"\nfile = \"" + floor + "\"\nfriction = 0");
  scene.line("[[body]]\nname = \"slider\"\n" + body + "friction = 0\nrestitution = 0\nposition = " +
             SceneText::vector(Vec3(0, half_height, 0)) + "\nvelocity = " +
             SceneText::vector(Vec3(speed * std::cos(heading), 0, speed * std::sin(heading))));
  return scene.str();
}

// A ball let go from rest 8-12 degrees up the side of a bowl whose rings are half a degree apart:
// on a flat triangle the slope is the triangle's, and only where the swing spans many of them does
// the faceted bowl pull as the sphere does. (12 degrees lengthens the period by 0.3 %: 1 + a^2/16.)
struct Bowl {
  double radius, ball, angle;
};
Bowl bowl_of(Draw& draw) {
  const double radius = draw.uniform(0.6, 2);
  const double ball = draw.uniform(0.05, 0.2) * radius;
  const double angle = draw.uniform(8, 12) * std::numbers::pi / 180;
  return {radius, ball, angle};
}
std::string rolling_in_a_bowl(Draw& draw) {
  const Bowl b = bowl_of(draw);
  const std::string bowl = obj_file(bowl_obj(b.radius, 20 * std::numbers::pi / 180, 40, 96));
  const double from_centre = b.radius - b.ball;
  SceneText scene("a ball rolling in a bowl", 12);
  scene.line("[world]\nsleeping = false");
  scene.line("[[body]]\nname = \"bowl\"\nshape = \"mesh\"\nfile = \"" + bowl + "\"\nfriction = 1");
  scene.line("[[body]]\nname = \"ball\"\nshape = \"sphere\"\nradius = " + SceneText::number(b.ball) +
             "\nfriction = 1\nrestitution = 0\nposition = " +
             SceneText::vector(Vec3(from_centre * std::sin(b.angle), -from_centre * std::cos(b.angle), 0)));
  return scene.str();
}

// Bodies of drawn shapes dropped on a bumpy ground.
std::string mesh_drops(Draw& draw) {
  const double a = draw.uniform(0.05, 0.3), k = draw.uniform(0.5, 2);
  const std::string ground = obj_file(ground_obj(draw, 5, draw.integer(8, 20), [&](double x, double z) {
    return a * std::sin(k * x) * std::cos(k * z);
  }));
  SceneText scene("bodies dropped on a bumpy mesh", 3);
  scene.line("[world]\nsleeping = false");
  scene.line("[[body]]\nname = \"ground\"\nshape = \"mesh\"\nfile = \"" + ground + "\"\nfriction = " +
             SceneText::number(draw.uniform(0, 1)));
  const int count = draw.integer(1, 6);
  for (int i = 0; i < count; ++i) {
    double half_height = 0;
    const std::string body = lying_body(draw, half_height);
    const Vec3 at = draw.vector(Vec3(-3, 1, -3), Vec3(3, 1, 3));
    const double restitution = draw.uniform(0, 1);
    scene.line("[[body]]\n" + body + "restitution = " + SceneText::number(restitution) + "\nposition = " +
               SceneText::vector(at + Vec3(0, 1.5 * i, 0)));
  }
  return scene.str();
}

TEST(MeshLaws, TheGeneratorsMakeTheSameScenesOnEveryBuild) {
  EXPECT_EQ(scenes_hash("mesh-sliding", sliding), 14758765206780128586u);
  EXPECT_EQ(scenes_hash("bowl-period", rolling_in_a_bowl), 1056503196896834331u);
  EXPECT_EQ(scenes_hash("mesh-drops", mesh_drops), 13625848473535939212u);
}

// A flat floor of triangles is a plane: a body sliding on it without friction keeps its velocity
// (within 0.5 % and 2 mm/s) and its height (1 mm), whatever seams it crosses.
TEST(MeshLaws, ABodySlidingOverAFlatMeshKeepsItsVelocity) {
  check_law("mesh-sliding", 60, sliding,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
              const physics::Body& body = world.bodies()[1];
              const Vec3 v0 = initial[1].velocity;
              const double change = (body.velocity - v0).norm();
              if (change > 0.005 * v0.norm() + 0.002) return breach_text("velocity changed by (m/s)", change, 0.005 * v0.norm() + 0.002);
              const double rise = std::abs(body.position.y() - initial[1].position.y());
              if (rise > 0.001) return breach_text("height changed by (m)", rise, 0.001);
              return std::string();
            });
}

// A ball rolling without slipping inside a sphere of radius R swings, for small angles, with the
// period 2 pi sqrt(7 (R - r) / (5 g)): its centre moves on a circle of R - r, and rolling adds
// 2/5 m r^2 to its inertia (the pendulum's length times 7/5). Measured between the first and the
// fourth time the centre passes the bottom going the same way: within 2 %.
TEST(MeshLaws, ABallRollingInABowlSwingsWithTheBowlsPeriod) {
  const int count = seeds_per_law(12);
  double worst = 0;
  for (uint64_t seed = first_seed(); seed < first_seed() + uint64_t(count); ++seed) {
    Draw draw = draw_for("bowl-period", seed);
    Draw again = draw_for("bowl-period", seed);
    const Bowl b = bowl_of(again);
    const double g = 9.81;
    const double expected = 2 * std::numbers::pi * std::sqrt(7 * (b.radius - b.ball) / (5 * g));
    std::vector<double> crossings;
    double last_x = 0;
    const std::string breach = run_case("bowl-period", seed, rolling_in_a_bowl(draw),
                                        [&](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>&) {
                                          const double x = world.bodies()[1].position.x();
                                          if (last_x > 0 && x <= 0)
                                            crossings.push_back(world.time() - world.settings().time_step * x / (x - last_x));
                                          last_x = x;
                                          return std::string();
                                        });
    ASSERT_TRUE(breach.empty()) << breach;
    ASSERT_GE(crossings.size(), 4u) << "seed " << seed << ": the ball crossed the bottom " << crossings.size() << " times";
    const double period = (crossings[3] - crossings[0]) / 3;
    worst = std::max(worst, std::abs(period / expected - 1));
    EXPECT_NEAR(period / expected, 1, 0.02) << "seed " << seed << ": R " << b.radius << " m, r " << b.ball << " m, period "
                                            << period << " s, expected " << expected << " s";
  }
  std::printf("bowl-period: %d scenes, the period off the formula's by %.2f %% at most\n", count, 100 * worst);
}

// Nothing dropped on a bumpy ground of triangles gains energy (1 %; measured from y = 0, the
// ground's mid-height, which every drop starts above).
TEST(MeshLaws, BodiesDroppedOnABumpyMeshNeverGainEnergy) {
  check_law("mesh-drops", 40, mesh_drops,
            [](const physics::World& world, const physics::StepRecord& start, const std::vector<physics::Body>&) {
              const physics::StepRecord& now = world.record();
              const double before = start.kinetic_energy + start.potential_energy;
              const double energy = now.kinetic_energy + now.potential_energy;
              return energy > before * 1.01 ? breach_text("energy", energy, before * 1.01) : std::string();
            });
}

}  // namespace
}  // namespace impulse::demos::laws
