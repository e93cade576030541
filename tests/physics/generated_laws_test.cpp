// The laws over generated scenes, not only the scenes we thought of (generated_scenes.h: each case
// a seeded scene file, replayable).
#include "tests/physics/generated_scenes.h"

namespace impulse::demos {
namespace {

using namespace laws;
using physics::Real;
using physics::Vec3;

// A pack of equal balls, elastic and frictionless, in zero gravity: a row, a two-dimensional rack
// (3 to 15 balls) or a three-dimensional cluster (4 to 20), with gaps from touching to 2 mm,
// struck by a spinning cue ball at 0.5 to 10 m/s a little off the line of centres.
std::string elastic_pack(Draw& draw) {
  const double radius = draw.uniform(0.02, 0.1), mass = draw.uniform(0.1, 2);
  const double gap = draw.coin() ? 0 : draw.uniform(0, 0.002);
  const double pitch = 2 * radius + gap, row_pitch = pitch * std::sqrt(3.0) / 2;
  const int arrangement = draw.integer(0, 2);  // row, rack, cluster
  SceneText scene("elastic pack", 2.0);
  scene.line("[world]\ngravity = [0, 0, 0]\nfriction = false\nsleeping = false");
  auto ball = [&](const Vec3& at) { scene.sphere(at, radius, mass, Vec3::Zero(), 1, 0); };
  if (arrangement == 0) {
    const int n = draw.integer(2, 8);
    for (int i = 0; i < n; ++i) ball(Vec3(i * pitch, 0, 0));
  } else if (arrangement == 1) {
    const int rows = draw.integer(2, 5);
    for (int row = 0; row < rows; ++row)
      for (int k = 0; k <= row; ++k) ball(Vec3(row * row_pitch, (k - row / 2.0) * pitch, 0));
  } else {
    // Tetrahedral: each layer a smaller triangle in the hollows of the one below.
    const int layers = draw.integer(2, 4);
    for (int layer = 0; layer < layers; ++layer)
      for (int row = 0; row < layers - layer; ++row)
        for (int k = 0; k <= row; ++k)
          ball(Vec3(row * row_pitch + layer * pitch / std::sqrt(3.0), (k - row / 2.0) * pitch,
                    layer * pitch * std::sqrt(2.0 / 3.0)));
  }
  const double speed = draw.uniform(0.5, 10);
  const double aim_y = draw.uniform(-0.2, 0.2), aim_z = arrangement == 2 ? draw.uniform(-0.2, 0.2) : 0;
  const Vec3 aim = Vec3(1, aim_y, aim_z).normalized();
  // Spinning as a cue ball that has slid along the cloth may (up to rolling, v / R): frictionless,
  // its spin is its own and must not change at the hits.
  const Vec3 spin = vector_of_length(draw, 0, speed / radius);
  scene.sphere(-aim * (2 * radius + draw.uniform(0.01, 0.3)), radius, mass, aim * speed, 1, 0, spin);
  return scene.str();
}

// Spheres and boxes of any material thrown at each other in zero gravity, spinning.
std::string free_collisions(Draw& draw) {
  SceneText scene("free collisions", 3.0);
  scene.line("[world]\ngravity = [0, 0, 0]");
  Placement placement(draw, Vec3(-2, -2, -2), Vec3(2, 2, 2));
  const int count = draw.integer(2, 8);
  for (int i = 0; i < count; ++i) {
    const double restitution = draw.uniform(0, 1), friction = draw.uniform(0, 1), mass = draw.uniform(0.2, 5);
    if (draw.coin()) {
      const double radius = draw.uniform(0.1, 0.4);
      const Vec3 at = placement.place(radius);
      scene.sphere(at, radius, mass, toward_middle(draw, at), restitution, friction);
    } else {
      const Vec3 size = draw.vector(0.1, 0.8);
      const Vec3 at = placement.place(size.norm() / 2);
      const Vec3 velocity = toward_middle(draw, at);
      const Vec3 spin = vector_of_length(draw, 0, 6);
      scene.box(at, size, mass, velocity, spin, draw.vector(0, 90), restitution, friction);
    }
  }
  return scene.str();
}

// Spheres and boxes dropped onto the ground, thrown and spinning, any material.
std::string drops(Draw& draw) {
  SceneText scene("drops", 4.0);
  scene.line("[world]\nsleeping = " + std::string(draw.coin() ? "true" : "false"));
  const double ground_restitution = draw.uniform(0, 1), ground_friction = draw.uniform(0, 1);
  scene.line("[[body]]\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0\nrestitution = " +
             SceneText::number(ground_restitution) + "\nfriction = " + SceneText::number(ground_friction));
  Placement placement(draw, Vec3(-3, 0.8, -3), Vec3(3, 4, 3));
  const int count = draw.integer(1, 10);
  for (int i = 0; i < count; ++i) {
    const double restitution = draw.uniform(0, 1), friction = draw.uniform(0, 1), mass = draw.uniform(0.2, 5);
    const Vec3 velocity = vector_of_length(draw, 0, 3);
    if (draw.coin()) {
      const double radius = draw.uniform(0.1, 0.5);
      scene.sphere(placement.place(radius), radius, mass, velocity, restitution, friction);
    } else {
      const Vec3 size = draw.vector(0.2, 1);
      const Vec3 at = placement.place(size.norm() / 2);
      const Vec3 spin = vector_of_length(draw, 0, 5);
      scene.box(at, size, mass, velocity, spin, draw.vector(0, 90), restitution, friction);
    }
  }
  return scene.str();
}

// Bodies far apart drifting slowly, with sleeping on (the default): in zero gravity; or a ball
// sliding on a frictionless floor.
std::string drifts(Draw& draw) {
  SceneText scene("drifts", 4.0);
  if (draw.coin()) {
    scene.line("[world]\ngravity = [0, 0, 0]");
    const int count = draw.integer(1, 4);
    for (int i = 0; i < count; ++i) {
      const double y = draw.uniform(-1, 1), z = draw.uniform(-1, 1);
      const Vec3 at(4.0 * i, y, z);
      const Vec3 velocity = vector_of_length(draw, 0.005, 0.1);
      if (draw.coin()) {
        const double radius = draw.uniform(0.1, 0.5), mass = draw.uniform(0.2, 5);
        scene.sphere(at, radius, mass, velocity, 0.5, 0.5);
      } else {
        const Vec3 size = draw.vector(0.2, 1);
        const double mass = draw.uniform(0.2, 5), turned = draw.uniform(0, 90);
        scene.box(at, size, mass, velocity, Vec3::Zero(), Vec3(turned, 0, 0), 0.5, 0.5);
      }
    }
  } else {
    scene.line("[world]\nfriction = false");
    scene.line("[[body]]\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0");
    const double radius = draw.uniform(0.1, 0.5), mass = draw.uniform(0.2, 5);
    const double vx = draw.uniform(0.005, 0.1), vz = draw.uniform(-0.05, 0.05);
    scene.sphere(Vec3(0, radius, 0), radius, mass, Vec3(vx, 0, vz), 0.5, 0.5);
  }
  return scene.str();
}

// A blackboard's collisions (planar = "xy"): spheres and boxes in the plane z = 0, boxes turned
// about z only, frictionless, of any restitution, thrown at each other in zero gravity; each also
// given a velocity out of the plane and a spin about x and y, which the lock takes at the start.
std::string planar_collisions(Draw& draw) {
  SceneText scene("planar collisions", 3.0);
  scene.line("[world]\ngravity = [0, 0, 0]\nfriction = false\nplanar = \"xy\"");
  Placement placement(draw, Vec3(-2, -2, 0), Vec3(2, 2, 0));
  const int count = draw.integer(2, 8);
  for (int i = 0; i < count; ++i) {
    const double restitution = draw.uniform(0, 1), mass = draw.uniform(0.2, 5);
    const Vec3 out_of_plane(0, 0, draw.uniform(-1, 1));
    const Vec3 spin = draw.vector(Vec3(-3, -3, -6), Vec3(3, 3, 6));
    if (draw.coin()) {
      const double radius = draw.uniform(0.1, 0.4);
      const Vec3 at = placement.place(radius);
      scene.sphere(at, radius, mass, Vec3(-at.normalized() * draw.uniform(0.2, 4)) + out_of_plane, restitution, 0, spin);
    } else {
      const Vec3 size = draw.vector(0.1, 0.8);
      const Vec3 at = placement.place(size.norm() / 2);
      const double speed = draw.uniform(0.2, 4), turned = draw.uniform(0, 90);
      scene.box(at, size, mass, Vec3(-at.normalized() * speed) + out_of_plane, spin, Vec3(0, 0, turned), restitution, 0);
    }
  }
  return scene.str();
}

// Section 5's shapes among the others: spheres, boxes, capsules and cylinders thrown at each other
// in zero gravity (free-round-collisions), or dropped onto the ground (round-drops), spinning, any
// material.
void any_shape(Draw& draw, SceneText& scene, Placement& placement, bool free) {
  const double restitution = draw.uniform(0, 1), friction = draw.uniform(0, 1), mass = draw.uniform(0.2, 5);
  const int shape = draw.integer(0, 3);
  const double radius = draw.uniform(0.08, 0.4), height = draw.uniform(0.05, 0.8);
  const Vec3 size = draw.vector(0.1, 0.8);
  const double reach = shape == 0 ? radius : shape == 1 ? size.norm() / 2 : shape == 2 ? height / 2 + radius : std::hypot(radius, height / 2);
  const Vec3 at = placement.place(reach);
  const Vec3 velocity = free ? toward_middle(draw, at) : vector_of_length(draw, 0, 3);
  const Vec3 spin = vector_of_length(draw, 0, 6), turned = draw.vector(0, 90);
  if (shape == 0) scene.sphere(at, radius, mass, velocity, restitution, friction, spin);
  else if (shape == 1) scene.box(at, size, mass, velocity, spin, turned, restitution, friction);
  else scene.round(shape == 2 ? "capsule" : "cylinder", at, radius, height, mass, velocity, spin, turned, restitution, friction);
}

// Bodies that `add` draws thrown at each other in zero gravity, or dropped onto the ground.
using AddBody = void (*)(Draw&, SceneText&, Placement&, bool free);

std::string thrown_together(Draw& draw, const char* title, AddBody add) {
  SceneText scene(title, 3.0);
  scene.line("[world]\ngravity = [0, 0, 0]");
  Placement placement(draw, Vec3(-2, -2, -2), Vec3(2, 2, 2));
  const int count = draw.integer(2, 8);
  for (int i = 0; i < count; ++i) add(draw, scene, placement, true);
  return scene.str();
}

std::string dropped(Draw& draw, const char* title, AddBody add) {
  SceneText scene(title, 4.0);
  scene.line("[world]\nsleeping = " + std::string(draw.coin() ? "true" : "false"));
  // Drawn one statement each: the operands of + are evaluated in an order the compiler chooses.
  const double ground_restitution = draw.uniform(0, 1), ground_friction = draw.uniform(0, 1);
  scene.line("[[body]]\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0\nrestitution = " + SceneText::number(ground_restitution) +
             "\nfriction = " + SceneText::number(ground_friction));
  Placement placement(draw, Vec3(-3, 1.0, -3), Vec3(3, 4, 3));
  const int count = draw.integer(1, 10);
  for (int i = 0; i < count; ++i) add(draw, scene, placement, false);
  return scene.str();
}

std::string free_round_collisions(Draw& draw) { return thrown_together(draw, "free collisions of every shape", any_shape); }
std::string round_drops(Draw& draw) { return dropped(draw, "drops of every shape", any_shape); }

// A stack of 2 to 6 cylinders standing face on face (or capsules lying crosswise, each across the
// one below), each of its own radius and mass, on the ground, sleeping off.
std::string round_stack(Draw& draw) {
  SceneText scene("a stack of cylinders", 5.0);
  scene.line("[world]\nsleeping = false");
  scene.line("[[body]]\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0");
  const int count = draw.integer(2, 6);
  const bool capsules = draw.coin();
  const double friction = draw.uniform(0.4, 1);
  double y = 0;
  for (int i = 0; i < count; ++i) {
    const double radius = draw.uniform(0.15, 0.4), height = draw.uniform(0.1, 0.6), mass = draw.uniform(0.5, 5);
    if (capsules) {
      // Lying, along x and z in turn: each rests on the one below at one point, held by friction.
      scene.round("capsule", Vec3(0, y + radius, 0), radius, height, mass, Vec3::Zero(), Vec3::Zero(),
                  i % 2 == 0 ? Vec3(0, 0, 90) : Vec3(90, 0, 0), 0, friction);
      y += 2 * radius;
    } else {
      scene.round("cylinder", Vec3(0, y + height / 2, 0), radius, height, mass, Vec3::Zero(), Vec3::Zero(), Vec3(0, draw.uniform(0, 90), 0), 0,
                  friction);
      y += height;
    }
  }
  return scene.str();
}

// A convex hull's fields: a wedge, a regular tetrahedron, a prism of 3 to 8 sides, or the hull of
// 5 to 12 points drawn in a box; `reach`, its farthest point from the points' origin.
std::string any_hull_fields(Draw& draw, double& reach) {
  const int kind = draw.integer(0, 3);
  if (kind == 0) {
    const Vec3 size = draw.vector(0.1, 0.8);
    reach = size.norm() / 2;
    return "shape = \"wedge\"\nsize = " + SceneText::vector(size);
  }
  if (kind == 1) {
    const double edge = draw.uniform(0.15, 0.8);
    reach = edge * std::sqrt(6.0) / 4;  // the circumradius
    return "shape = \"tetrahedron\"\nsize = " + SceneText::number(edge);
  }
  if (kind == 2) {
    const int sides = draw.integer(3, 8);
    const double radius = draw.uniform(0.08, 0.4);
    const double height = draw.uniform(0.05, 0.8);
    reach = std::hypot(radius, height / 2);
    return "shape = \"prism\"\nsides = " + std::to_string(sides) + "\nradius = " + SceneText::number(radius) +
           "\nheight = " + SceneText::number(height);
  }
  const int count = draw.integer(5, 12);
  const Vec3 half = draw.vector(0.05, 0.4);
  std::string points = "shape = \"hull\"\npoints = [";
  reach = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3 p = draw.vector(-half, half);
    reach = std::max(reach, p.norm());
    points += (i ? ", " : "") + SceneText::vector(p);
  }
  return points + "]";
}

// Hulls among every other shape: each body a hull or any_shape's.
void any_shape_or_hull(Draw& draw, SceneText& scene, Placement& placement, bool free) {
  if (!draw.coin()) return any_shape(draw, scene, placement, free);
  const double restitution = draw.uniform(0, 1), friction = draw.uniform(0, 1), mass = draw.uniform(0.2, 5);
  double reach = 0;
  const std::string fields = any_hull_fields(draw, reach);
  const Vec3 at = placement.place(reach);
  const Vec3 velocity = free ? toward_middle(draw, at) : vector_of_length(draw, 0, 3);
  const Vec3 spin = vector_of_length(draw, 0, 6), turned = draw.vector(0, 90);
  scene.shaped(fields, at, mass, velocity, spin, turned, restitution, friction);
}

std::string free_hull_collisions(Draw& draw) { return thrown_together(draw, "free collisions of hulls and every shape", any_shape_or_hull); }
std::string hull_drops(Draw& draw) { return dropped(draw, "drops of hulls and every shape", any_shape_or_hull); }

// A stack of 2 to 6 prisms of 3 to 8 sides standing on their ends, each of its own size and mass
// and turned about the vertical at random, on the ground, sleeping off.
std::string hull_stack(Draw& draw) {
  SceneText scene("a stack of prisms", 5.0);
  scene.line("[world]\nsleeping = false");
  scene.line("[[body]]\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0");
  const int count = draw.integer(2, 6);
  const double friction = draw.uniform(0.4, 1);
  double y = 0;
  for (int i = 0; i < count; ++i) {
    const int sides = draw.integer(3, 8);
    const double radius = draw.uniform(0.15, 0.4), height = draw.uniform(0.1, 0.6), mass = draw.uniform(0.5, 5);
    const double turn = draw.uniform(0, 90);
    scene.shaped("shape = \"prism\"\nsides = " + std::to_string(sides) + "\nradius = " + SceneText::number(radius) +
                     "\nheight = " + SceneText::number(height),
                 Vec3(0, y + height / 2, 0), mass, Vec3::Zero(), Vec3::Zero(), Vec3(0, turn, 0), 0, friction);
    y += height;
  }
  return scene.str();
}

// A pyramid of boxes (2 to 8 rows) of any size, mass and friction from 0.4, built as the
// benchmark builds it (rows touching), sleeping off.
std::string pyramid(Draw& draw) {
  SceneText scene("pyramid", 5.0);
  scene.line("[world]\nsleeping = false");
  scene.line("[[body]]\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0");
  const int base = draw.integer(2, 8);
  const double size = draw.uniform(0.2, 2), mass = draw.uniform(0.5, 50), friction = draw.uniform(0.4, 1);
  scene.line("[[pyramid]]\nbase = " + std::to_string(base) + "\nsize = " + SceneText::number(size) +
             "\nmass = " + SceneText::number(mass) + "\nfriction = " + SceneText::number(friction) + "\nrestitution = 0");
  return scene.str();
}

}  // namespace

// No body but the first (the ground) moves farther than `most` from where it started.
Law stays_within(double most) {
  return [most](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
    for (size_t i = 1; i < initial.size(); ++i) {
      const double moved = (world.bodies()[i].position - initial[i].position).norm();
      if (moved > most) return breach_text(("body " + std::to_string(i) + " moved").c_str(), moved, most);
    }
    return std::string();
  };
}

// With gravity: kinetic plus potential energy never rises above its start (by more than 1 %).
Law energy_never_rises() {
  return [](const physics::World& world, const physics::StepRecord& start, const std::vector<physics::Body>&) {
    const physics::StepRecord& now = world.record();
    const double before = start.kinetic_energy + start.potential_energy;
    const double energy = now.kinetic_energy + now.potential_energy;
    return energy > before * 1.01 ? breach_text("energy", energy, before * 1.01) : std::string();
  };
}

// Without external forces, momentum is kept to rounding (every impulse acts on both bodies), and
// angular momentum but for the soft step's own error, bounded step by step: each contact's impulse
// acts at lever arms taken at the start of the step (Box2D v3's soft step, physics/README.md), so
// as the two bodies move and turn within the step the points where it acts on each drift apart by
// at most the distance their surfaces travel, d = (|v_a| + |v_b| + |w_a| r_a + |w_b| r_b) dt, and
// the pair's torques about the origin differ by at most |J| d. (A lever arm wrong by a body's size
// would be many times that.) `energy_law` checks the kinetic energy against the start's.
Law momenta_law(std::function<std::string(double energy, double start_energy)> energy_law) {
  struct Drift {
    double allowed = 0;                 // the angular momentum the soft step may have moved so far
    std::vector<physics::Body> before;  // the bodies at the start of the step
  };
  auto drift = std::make_shared<Drift>();
  return [drift, energy_law](const physics::World& world, const physics::StepRecord& start,
                             const std::vector<physics::Body>& initial) {
    if (world.step_count() == 1) *drift = {0, initial};
    const physics::StepRecord& now = world.record();
    auto travel = [&](int body) {
      double fastest = 0;
      for (const std::vector<physics::Body>* bodies : {&std::as_const(drift->before), &world.bodies()}) {
        const physics::Body& b = (*bodies)[size_t(body)];
        fastest = std::max(fastest, b.velocity.norm() + b.angular_velocity.norm() * physics::bounding_radius(b.shape));
      }
      return fastest * world.settings().time_step;
    };
    for (const physics::ContactRecord& contact : now.contacts) {
      const double impulse = (contact.normal * contact.normal_impulse + contact.tangent_impulse).norm();
      drift->allowed += impulse * (travel(contact.body_a) + travel(contact.body_b));
    }
    drift->before = world.bodies();
    if (std::string breach = energy_law(now.kinetic_energy, start.kinetic_energy); !breach.empty()) return breach;
    double momentum_scale = 0;
    for (const physics::Body& body : initial) momentum_scale += body.mass * body.velocity.norm();
    const double momentum_change = (now.linear_momentum - start.linear_momentum).norm();
    if (momentum_change > 1e-9 * momentum_scale)
      return breach_text("momentum changed by", momentum_change, 1e-9 * momentum_scale);
    const double angular_change = (now.angular_momentum - start.angular_momentum).norm();
    if (angular_change > drift->allowed + 1e-9 * momentum_scale)
      return breach_text("angular momentum changed by", angular_change, drift->allowed);
    return std::string();
  };
}

// Elastic packs: kinetic energy within 1 % (eq. 5 with e = 1 for every pair, in whatever order
// the surfaces meet); momentum and angular momentum kept. 400 packs, a second in all, so that the
// rarer arrangements (a touching rack whose hits come at a sub-step's end) are among them.
TEST(GeneratedLaws, ElasticPacksKeepEnergyMomentumAndAngularMomentum) {
  check_law("elastic-pack", 400, elastic_pack, momenta_law([](double energy, double start_energy) {
              const double change = std::abs(energy / start_energy - 1);
              return change > 0.01 ? breach_text("kinetic energy changed by the share", change, 0.01) : std::string();
            }));
}

// Without external forces, whatever the shapes and materials: momentum and angular momentum kept,
// and the kinetic energy never rises (every e <= 1).
TEST(GeneratedLaws, WithoutExternalForcesMomentaAreKeptAndEnergyNeverRises) {
  check_law("free-collisions", 60, free_collisions, momenta_law([](double energy, double start_energy) {
              return energy > start_energy * 1.01 ? breach_text("kinetic energy", energy, start_energy * 1.01)
                                                  : std::string();
            }));
}

// A planar scene's frictionless impacts: momentum in the plane and angular momentum about its
// normal kept, the kinetic energy never rises, and every body stays in the plane (its z as it
// started, to rounding), turning about z alone.
TEST(GeneratedLaws, PlanarImpactsKeepMomentumInThePlane) {
  const Law momenta = momenta_law([](double energy, double start_energy) {
    return energy > start_energy * 1.01 ? breach_text("kinetic energy", energy, start_energy * 1.01) : std::string();
  });
  check_law("planar-collisions", 60, planar_collisions,
            [momenta](const physics::World& world, const physics::StepRecord& start, const std::vector<physics::Body>& initial) {
              for (size_t i = 0; i < initial.size(); ++i) {
                const physics::Body& body = world.bodies()[i];
                const double off = std::abs(body.position.z() - initial[i].position.z());
                if (off > 1e-9) return breach_text(("body " + std::to_string(i + 1) + " left the plane by").c_str(), off, 1e-9);
                const double tilt = std::hypot(body.angular_velocity.x(), body.angular_velocity.y());
                if (tilt > 1e-12) return breach_text(("body " + std::to_string(i + 1) + " turns about x or y at").c_str(), tilt, 1e-12);
              }
              return momenta(world, start, initial);
            });
}

// With gravity: kinetic plus potential energy never rises above its start (by more than 1 % of
// the energy above the ground).
TEST(GeneratedLaws, WithGravityEnergyNeverRisesAboveItsStart) {
  check_law("drops", 60, drops, energy_never_rises());
}

// Newton's first law with sleeping on: a body nothing holds keeps its velocity, and its centre is
// where x0 + v t puts it (across gravity, for a ball on a frictionless floor, which holds it up).
TEST(GeneratedLaws, UnsupportedBodiesKeepTheirVelocity) {
  check_law("drifts", 40, drifts,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
              const Vec3 gravity = world.settings().gravity;
              const auto across = [&](const Vec3& v) -> Vec3 {
                return gravity.isZero() ? v : Vec3(v - v.dot(gravity.normalized()) * gravity.normalized());
              };
              for (size_t i = 0; i < initial.size(); ++i) {
                if (initial[i].is_static()) continue;
                const physics::Body& body = world.bodies()[i];
                const double speed_change = across(body.velocity - initial[i].velocity).norm();
                if (speed_change > 1e-9) return breach_text("velocity changed by", speed_change, 1e-9);
                const Vec3 expected = initial[i].position + initial[i].velocity * world.time();
                const double off = across(body.position - expected).norm();
                if (off > 1e-6) return breach_text("centre off x0 + v t by", off, 1e-6);
              }
              return std::string();
            });
}

// The benchmark's stacks hold: no box of a pyramid moves more than 1 cm (or 2 % of its size).
TEST(GeneratedLaws, PyramidsHold) {
  check_law("pyramid", 24, pyramid,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
              for (size_t i = 0; i < initial.size(); ++i) {
                if (initial[i].is_static()) continue;
                const double size = 2 * physics::bounding_radius(initial[i].shape) / std::sqrt(3.0);
                const double limit = std::max(0.01, 0.02 * size);
                const double moved = (world.bodies()[i].position - initial[i].position).norm();
                if (moved > limit) return breach_text(("box " + std::to_string(i) + " moved").c_str(), moved, limit);
              }
              return std::string();
            });
}

// The same laws with capsules and cylinders among the spheres and boxes: every pair of shapes.
TEST(GeneratedLaws, EveryPairOfShapesKeepsMomentaAndNeverGainsEnergy) {
  check_law("free-round-collisions", 40, free_round_collisions, momenta_law([](double energy, double start_energy) {
              return energy > start_energy * 1.01 ? breach_text("kinetic energy", energy, start_energy * 1.01) : std::string();
            }));
  check_law("round-drops", 40, round_drops, energy_never_rises());
}

// The same with convex hulls (wedges, tetrahedra, prisms, the hulls of random points) among them.
TEST(GeneratedLaws, HullsAmongEveryShapeKeepMomentaAndNeverGainEnergy) {
  check_law("free-hull-collisions", 40, free_hull_collisions, momenta_law([](double energy, double start_energy) {
              return energy > start_energy * 1.01 ? breach_text("kinetic energy", energy, start_energy * 1.01) : std::string();
            }));
  check_law("hull-drops", 40, hull_drops, energy_never_rises());
}

// Stacks of prisms stand: no body moves more than 1 cm in 5 s.
TEST(GeneratedLaws, StacksOfPrismsHold) {
  check_law("hull-stack", 20, hull_stack, stays_within(0.01));
}

// Stacks of cylinders and of crossed capsules stand: no body moves more than 1 cm in 5 s.
TEST(GeneratedLaws, StacksOfCylindersAndCapsulesHold) {
  check_law("round-stack", 20, round_stack, stays_within(0.01));
}

// A light box (0.27 kg) pinched between two heavy balls (2.5 and 2.9 kg), frictionless, in the
// plane (planar-collisions, seed 3617 of the generator as it was): the contact that holds the box
// against one ball carries last sub-step's impulse into the next (the warm start), which throws the
// box at the other ball. That is a load, not an approach, and is not bounced: the energy never
// rises (it doubled in four sub-steps when the bounce took it for an approach).
TEST(GeneratedLaws, ALightBoxPinchedBetweenTwoHeavyBallsGainsNoEnergy) {
  const std::string scene = R"([scene]
title = "planar collisions"
duration = 3
[world]
gravity = [0, 0, 0]
friction = false
planar = "xy"
[[body]]
shape = "sphere"
radius = 0.13777286356203988
mass = 2.5232201583586966
position = [-1.3512856821084047, -1.124436786595902, 0.0]
velocity = [0.24208140095673303, 0.20144166121978174, -0.91160837448394183]
angular_velocity = [2.834202928129967, 0.62073299931631798, 1.2510931047948093]
restitution = 0.16204974994714116
friction = 0.0
[[body]]
shape = "sphere"
radius = 0.2845839649915205
mass = 3.2152212065448222
position = [-0.080718182616589473, 0.90496100266919965, 0.0]
velocity = [0.18604040045758485, -2.085766823254438, 0.46298513775310557]
angular_velocity = [1.1994926410304254, -2.1365090736602319, -5.8810783765621082]
restitution = 0.69182797695514464
friction = 0.0
[[body]]
shape = "box"
size = [0.67362339862097709, 0.16306450497037245, 0.35658461739344449]
mass = 0.26853954986946749
position = [1.5590873571403479, 1.0641182883170943, 0.0]
velocity = [-2.5715544943619442, -1.7551538432546157, -0.16275545233684818]
angular_velocity = [-2.0404893937856734, 1.6337865449734084, -0.8110517510675308]
rotation = [0.0, 0.0, 39.681848914871118]
restitution = 0.55244947996144811
friction = 0.0
[[body]]
shape = "sphere"
radius = 0.11448184713615916
mass = 4.8532587257298809
position = [0.87958403953447561, 1.3244328384443822, 0.0]
velocity = [-0.56192824147261233, -0.84612291993101996, 0.11718831220245107]
angular_velocity = [-2.753497994107807, 1.5494107770314933, 3.4256635951243233]
restitution = 0.21224986817725799
friction = 0.0
[[body]]
shape = "sphere"
radius = 0.12820469320235517
mass = 2.5528484972781462
position = [1.4369066130827717, -1.2123028589036111, 0.0]
velocity = [-1.8450458153222926, 1.5566455720630141, -0.46130308432688416]
angular_velocity = [1.799152071057601, -2.4238834655788395, -4.4494022716391184]
restitution = 0.48336427153406225
friction = 0.0
[[body]]
shape = "sphere"
radius = 0.29923374390963597
mass = 2.8527387790707963
position = [-0.075000573833352124, 1.716111413718008, 0.0]
velocity = [0.17357789473126964, -3.971689696392835, -0.4765237014617234]
angular_velocity = [-1.5027450034648091, -0.88906797688001848, -1.6919076086984042]
restitution = 0.065021377813761161
friction = 0.0
)";
  const std::string breach = run_case("pinched-box", 3617, scene, momenta_law([](double energy, double start_energy) {
    return energy > start_energy * 1.01 ? breach_text("kinetic energy", energy, start_energy * 1.01) : std::string();
  }));
  EXPECT_EQ(breach, "");
}

// A seed printed by one build replays as the same scene in every other (GCC's Release suite,
// clang's sanitizer builds): each generator's first 20 scenes, as text, hash alike in each.
TEST(GeneratedLaws, ASeedIsTheSameSceneWhateverTheCompiler) {
  EXPECT_EQ(scenes_hash("elastic-pack", elastic_pack), 0x888a113abe5bf66bull);
  EXPECT_EQ(scenes_hash("free-collisions", free_collisions), 0xdf386f4987990e7eull);
  EXPECT_EQ(scenes_hash("planar-collisions", planar_collisions), 0x775794f2f28d8244ull);
  EXPECT_EQ(scenes_hash("drops", drops), 0x7923258a195e1aafull);
  EXPECT_EQ(scenes_hash("drifts", drifts), 0xfa42999f856add0eull);
  EXPECT_EQ(scenes_hash("pyramid", pyramid), 0xe3905eb0c0c3310full);
  EXPECT_EQ(scenes_hash("free-round-collisions", free_round_collisions), 0x899ff0751a0244acull);
  EXPECT_EQ(scenes_hash("round-drops", round_drops), 0x3545382489a9e7cbull);
  EXPECT_EQ(scenes_hash("round-stack", round_stack), 0xeeb0c6b75f8bb92dull);
  EXPECT_EQ(scenes_hash("free-hull-collisions", free_hull_collisions), 0x02cde50475c606b7ull);
  EXPECT_EQ(scenes_hash("hull-drops", hull_drops), 0xc3cddb306df9bbf4ull);
  EXPECT_EQ(scenes_hash("hull-stack", hull_stack), 0x4bc1d31a60fa22a7ull);
}

}  // namespace impulse::demos
