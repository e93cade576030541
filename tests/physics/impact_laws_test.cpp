// The moment of impact as laws over generated scenes (generated_scenes.h): spheres and cubes thrown
// at a still surface (the ground, a plane at any angle, a static box turned any way), sliding and
// spinning, any friction and restitution. Gravity is off, so the motion before the impact is known
// exactly; the outcome is the impact model of physics/README.md ("The moment of impact"), computed
// here from the body's state at the moment of contact:
//   1. Newton's restitution at the contact point (eq. 5, 8-14): J = -(1 + e) v_n / (n . K n), with
//      K the point's effective mass matrix (eq. 13's denominator along any two directions);
//   2. then Coulomb friction at the point, from the velocity the normal impulse left: of the
//      impulses in the disc |j| <= mu J, the one that leaves the least kinetic energy (the point
//      stops sliding when that is within the disc, else it slides through the impact).
// Energy never rises, and a frictionless bounce never changes a sphere's spin.
#include "tests/physics/generated_scenes.h"

#include <algorithm>
#include <optional>

namespace impulse::demos {
namespace {

using namespace laws;
using physics::Mat3;
using physics::Quat;
using physics::Real;
using physics::Vec3;

constexpr double kStep = 1.0 / 60;

// A body's free motion in zero gravity (a sphere's or a cube's: the same inertia about every axis,
// so its angular velocity is constant): where it is and how it is turned after t.
struct FreeMotion {
  Vec3 x0, v, w;
  Quat q0;
  Vec3 at(double t) const { return x0 + v * t; }
  Quat turned(double t) const {
    const double angle = w.norm() * t;
    return angle > 0 ? Quat(Eigen::AngleAxis<double>(angle, w.normalized())) * q0 : q0;
  }
};

// The still surface the body is thrown at: a plane n . x = d (a static box's face, aimed at its
// middle, is such a plane there).
struct Surface {
  Vec3 n;
  double d;
  double height(const Vec3& p) const { return n.dot(p) - d; }
};

// The body's lowest point along the surface's normal after t, relative to its centre: a sphere's
// -R n, a cube's lowest corner.
Vec3 lowest_point(const physics::Body& body, const FreeMotion& motion, const Surface& surface, double t, int* corner = nullptr) {
  if (body.shape.type == physics::ShapeType::sphere) return -body.shape.radius * surface.n;
  const Mat3 r = motion.turned(t).toRotationMatrix();
  Vec3 best = Vec3::Zero();
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 8; ++i) {
    const Vec3 h = body.shape.half_extents;
    const Vec3 c = r * Vec3(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
    if (surface.n.dot(c) < lowest) lowest = surface.n.dot(c), best = c, corner && (*corner = i);
  }
  return best;
}

// When the body first touches the surface: scanned in steps of 0.1 ms, then halved 60 times.
std::optional<double> moment_of_contact(const physics::Body& body, const FreeMotion& motion, const Surface& surface, double until) {
  auto gap = [&](double t) { return surface.height(motion.at(t) + lowest_point(body, motion, surface, t)); };
  double before = 0;
  for (double t = 1e-4; t < until; t += 1e-4) {
    if (gap(t) > 0) {
      before = t;
      continue;
    }
    double low = before, high = t;
    for (int i = 0; i < 60; ++i) (gap((low + high) / 2) > 0 ? low : high) = (low + high) / 2;
    return high;
  }
  return std::nullopt;
}

struct Outcome {
  Vec3 v, w;
};

// The impact model (this file's first lines) for a body of mass m and world inverse inertia
// `inv_inertia` hitting a still surface with normal n at r from its centre.
Outcome impact_model(double m, const Mat3& inv_inertia, const Vec3& r, const Vec3& n, Outcome body, double e, double mu) {
  auto k = [&](const Vec3& a, const Vec3& b) { return a.dot(b) / m + r.cross(a).dot(inv_inertia * r.cross(b)); };
  auto apply = [&](const Vec3& impulse) {
    body.v += impulse / m;
    body.w += inv_inertia * r.cross(impulse);
  };
  const double jn = -(1 + e) * (body.v + body.w.cross(r)).dot(n) / k(n, n);
  apply(jn * n);
  Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const Vec3 sliding = body.v + body.w.cross(r);
  const Eigen::Vector2d vt(sliding.dot(t1), sliding.dot(t2));
  Eigen::Matrix2d kt;
  kt << k(t1, t1), k(t1, t2), k(t2, t1), k(t2, t2);
  Eigen::Vector2d j = -kt.inverse() * vt;
  const double limit = mu * jn;
  if (j.norm() > limit) {
    // On the rim: the angle that leaves the least energy, searched on a fine circle, then narrowed.
    auto energy = [&](double angle) {
      const Eigen::Vector2d x(limit * std::cos(angle), limit * std::sin(angle));
      return 0.5 * x.dot(kt * x) + x.dot(vt);
    };
    double best = 0;
    for (int i = 0; i < 3600; ++i)
      if (energy(i * 2 * M_PI / 3600) < energy(best)) best = i * 2 * M_PI / 3600;
    double low = best - 2 * M_PI / 3600, high = best + 2 * M_PI / 3600;
    for (int i = 0; i < 100; ++i) {
      const double a = low + (high - low) / 3, b = high - (high - low) / 3;
      (energy(a) < energy(b) ? high : low) = energy(a) < energy(b) ? b : a;
    }
    j = Eigen::Vector2d(limit * std::cos((low + high) / 2), limit * std::sin((low + high) / 2));
  }
  apply(j[0] * t1 + j[1] * t2);
  return body;
}

// Rotation degrees about x, then y, then z, each about the world axis (the scene files' rule).
Quat from_degrees(const Vec3& degrees) {
  auto about = [](double deg, const Vec3& axis) { return Quat(Eigen::AngleAxis<double>(deg * M_PI / 180, axis)); };
  return about(degrees.z(), Vec3::UnitZ()) * about(degrees.y(), Vec3::UnitY()) * about(degrees.x(), Vec3::UnitX());
}

// A sphere or a cube thrown at a still surface: which, and how, drawn until the impact is a single
// point that meets the surface once: a cube's corner clearly lowest, parting after the impact, and
// no other corner reaching the surface for 0.2 s after it, by the model's outcome.
std::string thrown_at_a_surface(Draw& draw) {
  for (;;) {
    std::ostringstream bodies;
    const int kind = draw.integer(0, 2);  // the ground, a plane at any angle, a static box's face
    Vec3 n = Vec3::UnitY(), on_surface = Vec3::Zero();
    const double e = draw.uniform(0, 1), mu = draw.coin() && draw.coin() ? 0.0 : draw.uniform(0, 1);
    const std::string material = "restitution = " + SceneText::number(e) + "\nfriction = " + SceneText::number(mu) + "\n";
    if (kind == 0) {
      bodies << "[[body]]\nname = \"surface\"\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0\n" << material;
    } else if (kind == 1) {
      n = direction(draw, false);
      const double offset = draw.uniform(-1, 1);
      bodies << "[[body]]\nname = \"surface\"\nshape = \"plane\"\nnormal = " << SceneText::vector(n) << "\noffset = "
             << SceneText::number(offset) << "\n" << material;
      on_surface = n * offset + n.unitOrthogonal() * draw.uniform(-1, 1);
    } else {
      const Vec3 degrees(draw.uniform(0, 360), draw.uniform(0, 360), draw.uniform(0, 360));
      const Vec3 centre(draw.uniform(-1, 1), draw.uniform(-1, 1), draw.uniform(-1, 1));
      bodies << "[[body]]\nname = \"surface\"\nshape = \"box\"\nstatic = true\nsize = [3, 0.4, 3]\nrotation = "
             << SceneText::vector(degrees) << "\nposition = " << SceneText::vector(centre) << "\n" << material;
      const Mat3 r = from_degrees(degrees).toRotationMatrix();
      n = r.col(1);
      on_surface = centre + r * Vec3(draw.uniform(-0.6, 0.6), 0.2, draw.uniform(-0.6, 0.6));
    }
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const double angle = draw.uniform(0, 2 * M_PI);
    const Vec3 sideways = (std::cos(angle) * t1 + std::sin(angle) * t2) * draw.uniform(0, 4);
    const Vec3 velocity = -n * draw.uniform(1, 6) + sideways;
    const Vec3 spin = direction(draw, false) * draw.uniform(0, 10);
    const double mass = draw.uniform(0.2, 5), t_hit = draw.uniform(0.05, 0.25);
    const bool sphere = draw.coin();
    const double size = sphere ? draw.uniform(0.05, 0.4) : draw.uniform(0.1, 0.6);
    const Vec3 degrees(draw.uniform(0, 360), draw.uniform(0, 360), draw.uniform(0, 360));
    // Placed so that, moving freely, its lowest point would reach `on_surface` after t_hit.
    physics::Body body;
    body.shape = sphere ? physics::Shape::sphere(size / 2) : physics::Shape::box(Vec3::Constant(size / 2));
    FreeMotion motion{Vec3::Zero(), velocity, spin, sphere ? Quat::Identity() : from_degrees(degrees)};
    const Surface surface{n, n.dot(on_surface)};
    motion.x0 = on_surface - lowest_point(body, motion, surface, t_hit) - velocity * t_hit;
    const std::optional<double> contact = moment_of_contact(body, motion, surface, 1.0);
    if (!contact) continue;
    if (!sphere) {
      // One corner first, by a clear margin, and none other for 0.2 s after (the model's motion).
      int first = -1;
      const Vec3 r = lowest_point(body, motion, surface, *contact, &first);
      const double inertia = mass * size * size / 6;
      const Outcome after = impact_model(mass, Mat3::Identity() / inertia, r, n, {velocity, spin}, e, mu);
      // The corner parts from the surface, by at least a quarter of its rebound: where friction
      // turns it back into the surface, the soft contact stops what is left (physics/README.md).
      const double rebound = -e * (velocity + spin.cross(r)).dot(n);
      if (!((after.v + after.w.cross(r)).dot(n) > std::max(0.01, rebound / 4))) continue;
      FreeMotion later{motion.at(*contact), after.v, after.w, motion.turned(*contact)};
      const Mat3 at_contact = motion.turned(*contact).toRotationMatrix();
      bool single = true;
      for (int i = 0; i < 8 && single; ++i) {
        if (i == first) continue;
        const Vec3 h = Vec3::Constant(size / 2);
        const Vec3 local(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z());
        single = surface.height(motion.at(*contact) + at_contact * local) > 0.01 * size;
        for (double t = 0; t <= 0.2 && single; t += 0.002)
          single = surface.height(later.at(t) + later.turned(t).toRotationMatrix() * local) > 0.005;
      }
      if (!single) continue;
    }
    const double duration = std::ceil((*contact + 0.15) / kStep) * kStep;
    std::ostringstream text;
    text << "[scene]\ntitle = \"thrown at a surface\"\nduration = " << SceneText::number(duration) << "\n"
         << "[world]\ngravity = [0, 0, 0]\nsleeping = false\n" << bodies.str();
    text << "[[body]]\nname = \"thrown\"\nshape = \"" << (sphere ? "sphere\"\nradius = " + SceneText::number(size / 2)
                                                              : "box\"\nsize = " + SceneText::vector(Vec3::Constant(size)))
         << "\nmass = " << SceneText::number(mass) << "\nposition = " << SceneText::vector(motion.x0)
         << "\nvelocity = " << SceneText::vector(velocity) << "\nangular_velocity = " << SceneText::vector(spin)
         << (sphere ? "" : "\nrotation = " + SceneText::vector(degrees)) << "\n" << material;
    return text.str();
  }
}

// The surface as the world built it: a plane, or the static box's face that the body is aimed at.
Surface surface_of(const physics::Body& still) {
  if (still.shape.type == physics::ShapeType::plane) {
    const double length = still.shape.normal.norm();
    return {still.shape.normal / length, still.shape.offset / length};
  }
  const Vec3 n = still.orientation * Vec3::UnitY();
  return {n, n.dot(still.position) + still.shape.half_extents.y()};
}

TEST(ImpactLaws, ABodyThrownAtAStillSurfaceLeavesAsTheImpactModelSays) {
  check_law("thrown-at-a-surface", 80, thrown_at_a_surface,
            [](const physics::World& world, const physics::StepRecord& start, const std::vector<physics::Body>& initial) {
              const physics::StepRecord& now = world.record();
              if (now.kinetic_energy > start.kinetic_energy * (1 + 1e-9))
                return breach_text("kinetic energy rose to", now.kinetic_energy, start.kinetic_energy);
              const physics::Body& before = initial[1];
              const physics::Body& body = world.bodies()[1];
              const physics::Material material = initial[0].material;
              // From 0.1 s after the moment of contact: the model's outcome.
              const FreeMotion motion{before.position, before.velocity, before.angular_velocity, before.orientation};
              const Surface surface = surface_of(initial[0]);
              const std::optional<double> contact = moment_of_contact(before, motion, surface, world.time());
              if (!contact || world.time() < *contact + 0.1) return std::string();
              const Vec3 r = lowest_point(before, motion, surface, *contact);
              const Mat3 turn = motion.turned(*contact).toRotationMatrix();
              const Mat3 inv_inertia = turn * before.inv_inertia_local * turn.transpose();
              const Outcome expected = impact_model(before.mass, inv_inertia, r, surface.n, {before.velocity, before.angular_velocity},
                                                    material.restitution, material.friction);
              const double scale = (before.velocity + before.angular_velocity.cross(r)).norm();
              const double reach = physics::bounding_radius(before.shape);
              if ((body.velocity - expected.v).norm() > 0.02 * scale)
                return breach_text("velocity off the model's by", (body.velocity - expected.v).norm(), 0.02 * scale);
              if ((body.angular_velocity - expected.w).norm() * reach > 0.02 * scale)
                return breach_text("spin off the model's by (as a speed at its reach)", (body.angular_velocity - expected.w).norm() * reach,
                                   0.02 * scale);
              if (material.friction == 0 && before.shape.type == physics::ShapeType::sphere &&
                  (body.angular_velocity - before.angular_velocity).norm() > 0.01)
                return breach_text("a frictionless bounce changed a sphere's spin by", (body.angular_velocity - before.angular_velocity).norm(),
                                   0.01);
              return std::string();
            });
}

}  // namespace
}  // namespace impulse::demos
