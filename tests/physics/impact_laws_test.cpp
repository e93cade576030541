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
// Energy never rises, and a frictionless bounce never changes a sphere's spin. And bodies that hang
// on joints take part in the impact with their joints held: eq. 5 at the contact, angular momentum
// about the fixed pivot kept, the joints holding. With gravity and the default settings, a body that
// falls or is pushed never sinks into another further than a frame shows: 5 mm, or a tenth of the
// thinner body's thinnest size.
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
      const Vec3 degrees = draw.vector(0, 360);
      const Vec3 centre = draw.vector(-1, 1);
      bodies << "[[body]]\nname = \"surface\"\nshape = \"box\"\nstatic = true\nsize = [3, 0.4, 3]\nrotation = "
             << SceneText::vector(degrees) << "\nposition = " << SceneText::vector(centre) << "\n" << material;
      const Mat3 r = from_degrees(degrees).toRotationMatrix();
      n = r.col(1);
      const double x = draw.uniform(-0.6, 0.6), z = draw.uniform(-0.6, 0.6);
      on_surface = centre + r * Vec3(x, 0.2, z);
    }
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const double angle = draw.uniform(0, 2 * M_PI);
    const Vec3 sideways = (std::cos(angle) * t1 + std::sin(angle) * t2) * draw.uniform(0, 4);
    const Vec3 velocity = -n * draw.uniform(1, 6) + sideways;
    const Vec3 spin = vector_of_length(draw, 0, 10);
    const double mass = draw.uniform(0.2, 5), t_hit = draw.uniform(0.05, 0.25);
    const bool sphere = draw.coin();
    const double size = sphere ? draw.uniform(0.05, 0.4) : draw.uniform(0.1, 0.6);
    const Vec3 degrees = draw.vector(0, 360);
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

// A body on joints to a fixed pivot at the origin struck by (or striking) a free ball, in zero
// gravity: a ball on a rod (a pendulum), a ball pinned by a ball joint outside it (a rigid
// pendulum), a plank on a hinge struck on one side of it (a seesaw), two balls on rods in a row (a
// chain). The jointed body turns about the pivot at 1 to 5 rad/s; the free ball waits on its path
// or falls onto the plank. Friction is off in half of them (there eq. 5 holds at the contact: with
// friction the tangential impulse changes the normal speed too, through the joints). Every other
// scene runs 1200 steps a second, so that the velocities just before and after the impact are the
// states around the step that holds it (a chain's links change their velocities on after it).
std::string jointed_impact(Draw& draw) {
  for (;;) {
    std::ostringstream text;
    const bool fine = draw.coin();
    const double e = draw.uniform(0, 1), mu = draw.coin() ? 0.0 : draw.uniform(0, 1);
    const std::string material = "restitution = " + SceneText::number(e) + "\nfriction = " + SceneText::number(mu) + "\n";
    text << "[scene]\ntitle = \"jointed impact\"\nduration = 0.6\n[world]\ngravity = [0, 0, 0]\nsleeping = false\nstep_rate = "
         << (fine ? 1200 : 60) << "\n";
    auto ball = [&](const std::string& name, const Vec3& at, double radius, double mass, const Vec3& velocity, const Vec3& spin) {
      text << "[[body]]\nname = \"" << name << "\"\nshape = \"sphere\"\nradius = " << SceneText::number(radius)
           << "\nmass = " << SceneText::number(mass) << "\nposition = " << SceneText::vector(at) << "\nvelocity = "
           << SceneText::vector(velocity) << "\nangular_velocity = " << SceneText::vector(spin) << "\n" << material;
    };
    const int kind = draw.integer(0, 3);  // pendulum on a rod, rigid pendulum, seesaw, chain
    const double speed = draw.uniform(1, 5), omega = draw.coin() ? speed : -speed;
    const Vec3 turning(0, 0, omega);
    const double free_radius = draw.uniform(0.05, 0.25), free_mass = draw.uniform(0.2, 5);
    if (kind == 2) {
      const double length = draw.uniform(1, 3), hinge = draw.uniform(-0.3, 0.3) * length, plank_mass = draw.uniform(0.5, 5);
      const double slow = draw.uniform(-0.5, 0.5);  // the plank's own turning, rad/s
      text << "[[body]]\nname = \"jointed\"\nshape = \"box\"\nsize = [" << SceneText::number(length) << ", 0.05, 0.3]\nmass = "
           << SceneText::number(plank_mass) << "\nposition = " << SceneText::vector(Vec3(-hinge, 0, 0)) << "\nvelocity = "
           << SceneText::vector(Vec3(0, slow * -hinge, 0)) << "\nangular_velocity = [0, 0, " << SceneText::number(slow) << "]\n"
           << material;
      text << "[[joint]]\ntype = \"hinge\"\na = \"jointed\"\nanchor = [0, 0, 0]\naxis = [0, 0, 1]\n";
      double along = draw.uniform(-0.45, 0.45) * length - hinge;
      if (std::abs(along) < 0.1) continue;
      const double fall = draw.uniform(1, 5), t_hit = draw.uniform(0.05, 0.25);
      const double drift = draw.uniform(-0.5, 0.5), z = draw.uniform(-0.1, 0.1), vx = draw.uniform(-0.5, 0.5);
      ball("free", Vec3(along + drift * t_hit, 0.025 + free_radius + fall * t_hit, z), free_radius, free_mass, Vec3(vx, -fall, 0),
           Vec3::Zero());
      return text.str();
    }
    // The free ball on the jointed ball's circle (a little off it: an oblique hit), ahead of it.
    const double length = draw.uniform(0.5, 1.5), radius = draw.uniform(0.05, 0.2), mass = draw.uniform(0.2, 5);
    const double at_hit = draw.uniform(0, 2 * M_PI), t_hit = draw.uniform(0.05, 0.3);
    const double start = at_hit - omega * t_hit - (omega > 0 ? 1 : -1) * (radius + free_radius) / length;
    auto on_circle = [](double r, double angle) { return Vec3(r * std::cos(angle), r * std::sin(angle), 0); };
    const Vec3 free_at = on_circle(length + draw.uniform(-0.7, 0.7) * (radius + free_radius), at_hit);
    if (kind == 3) {  // chain: an inner ball half way out, clear of the outer one and of the free ball
      if (length / 2 < 2 * radius + 0.05 || free_at.norm() - length / 2 < radius + free_radius + 0.05) continue;
      const Vec3 inner = on_circle(length / 2, start);
      ball("inner", inner, radius, mass, turning.cross(inner), Vec3::Zero());
    }
    const Vec3 at = on_circle(length, start);
    ball("jointed", at, radius, mass, turning.cross(at), kind == 1 ? turning : Vec3::Zero());
    if ((free_at - at).norm() < radius + free_radius + 0.01) continue;
    ball("free", free_at, free_radius, free_mass, Vec3::Zero(), Vec3::Zero());
    if (kind == 0) text << "[[joint]]\ntype = \"rod\"\na = \"world\"\nb = \"jointed\"\nanchor_a = [0, 0, 0]\nanchor_b = " << SceneText::vector(at) << "\n";
    if (kind == 1) text << "[[joint]]\ntype = \"ball\"\na = \"jointed\"\nanchor = [0, 0, 0]\n";
    if (kind == 3)
      text << "[[joint]]\ntype = \"rod\"\na = \"world\"\nb = \"inner\"\nanchor_a = [0, 0, 0]\nanchor_b = "
           << SceneText::vector(on_circle(length / 2, start)) << "\n[[joint]]\ntype = \"rod\"\na = \"inner\"\nb = \"jointed\"\n"
           << "anchor_a = " << SceneText::vector(on_circle(length / 2, start)) << "\nanchor_b = " << SceneText::vector(at) << "\n";
    return text.str();
  }
}

// Angular momentum about the origin (the pivot) of the moving bodies; about the hinge's axis alone
// where a hinge holds (it can take up a turn about any other axis).
Vec3 angular_momentum_about_pivot(const physics::World& world) {
  Vec3 l = Vec3::Zero();
  for (const physics::Body& b : world.bodies())
    if (!b.is_static()) l += b.position.cross(b.mass * b.velocity) + b.inertia_world() * b.angular_velocity;
  for (const physics::Joint& j : world.joints())
    if (j.type == physics::JointType::hinge) return Vec3(0, 0, l.z());
  return l;
}

// A body's point velocity, v + w x (p - x).
Vec3 point_velocity(const physics::Body& b, const Vec3& p) { return b.velocity + b.angular_velocity.cross(p - b.position); }

TEST(ImpactLaws, JointsTakePartInTheImpact) {
  struct Seen {
    std::vector<physics::Body> before;  // the bodies at the start of the step
    bool struck = false;
  };
  auto seen = std::make_shared<Seen>();
  check_law("jointed-impact", 80, jointed_impact,
            [seen](const physics::World& world, const physics::StepRecord& start, const std::vector<physics::Body>& initial) {
              if (world.step_count() == 1) *seen = {initial, false};
              const physics::StepRecord& now = world.record();
              const std::vector<physics::Body> before = std::exchange(seen->before, world.bodies());
              if (now.kinetic_energy > start.kinetic_energy * (1 + 1e-6))
                return breach_text("kinetic energy rose to", now.kinetic_energy, start.kinetic_energy);
              const Vec3 l0 = [&] {
                Vec3 l = Vec3::Zero();
                for (const physics::Body& b : initial)
                  if (!b.is_static()) l += b.position.cross(b.mass * b.velocity) + b.inertia_world() * b.angular_velocity;
                for (const physics::Joint& j : world.joints())
                  if (j.type == physics::JointType::hinge) return Vec3(0, 0, l.z());
                return l;
              }();
              const double l_change = (angular_momentum_about_pivot(world) - l0).norm();
              if (l_change > 1e-3 * l0.norm() + 1e-9)
                return breach_text("angular momentum about the pivot changed by", l_change, 1e-3 * l0.norm());
              for (const physics::JointRecord& j : now.joints) {
                const physics::Joint& joint = world.joints()[&j - now.joints.data()];
                const double off = joint.type == physics::JointType::distance ? std::abs((j.anchor_a - j.anchor_b).norm() - joint.length)
                                                                              : (j.anchor_a - j.anchor_b).norm();
                if (off > 0.001) return breach_text("a joint let go by (m)", off, 0.001);
              }
              // Eq. 5 at the contact, in the step that holds the first impact (1200 steps a second, no friction).
              const physics::Material material = initial.back().material;
              const bool fine = world.settings().time_step < 0.001;
              for (const physics::ContactRecord& c : now.contacts) {
                if (seen->struck || c.normal_impulse <= 0) continue;
                seen->struck = true;
                if (!fine || material.friction > 0 || material.restitution < 0.05) continue;
                auto normal_speed = [&](const std::vector<physics::Body>& bodies) {
                  return (point_velocity(bodies[c.body_a], c.point) - point_velocity(bodies[c.body_b], c.point)).dot(c.normal);
                };
                const double approach = normal_speed(before), parting = normal_speed(world.bodies());
                if (std::abs(parting + material.restitution * approach) > 0.02 * std::abs(approach))
                  return breach_text("eq. 5: parting at", parting, -material.restitution * approach);
              }
              return std::string();
            });
}

// A box dropped flat (its faces level, turned any way about the vertical), from 0.2 to 2 m, onto the
// ground or a static box, with gravity: its four corners land together, and it must not start to
// turn however the solver orders them (no spin above 0.01 rad/s), bouncing or at rest.
std::string flat_landing(Draw& draw) {
  const double e = draw.uniform(0, 1), mu = draw.uniform(0, 1);
  const std::string material = "restitution = " + SceneText::number(e) + "\nfriction = " + SceneText::number(mu) + "\n";
  std::ostringstream text;
  text << "[scene]\ntitle = \"flat landing\"\nduration = 2.0\n[world]\nsleeping = false\n";
  const bool on_box = draw.coin();
  const Vec3 size = draw.vector(Vec3(0.1, 0.05, 0.1), Vec3(1.5, 1, 1.5));
  const double floor = on_box ? 0.5 : 0;
  if (on_box)
    text << "[[body]]\nname = \"floor\"\nshape = \"box\"\nstatic = true\nsize = [6, 1, 6]\nrotation = [0, "
         << SceneText::number(draw.uniform(0, 90)) << ", 0]\n" << material;
  else
    text << "[[body]]\nname = \"floor\"\nshape = \"plane\"\nnormal = [0, 1, 0]\noffset = 0\n" << material;
  const double mass = draw.uniform(0.2, 20), x = draw.uniform(-1, 1), lift = draw.uniform(0.2, 2), z = draw.uniform(-1, 1);
  text << "[[body]]\nname = \"box\"\nshape = \"box\"\nsize = " << SceneText::vector(size) << "\nmass = "
       << SceneText::number(mass) << "\nposition = " << SceneText::vector(Vec3(x, floor + size.y() / 2 + lift, z))
       << "\nrotation = [0, " << SceneText::number(draw.uniform(0, 360)) << ", 0]\n" << material;
  return text.str();
}

TEST(ImpactLaws, ABoxLandingFlatDoesNotTurn) {
  check_law("flat-landing", 60, flat_landing,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>&) {
              const physics::Body& box = world.bodies()[1];
              if (box.angular_velocity.norm() > 0.01) return breach_text("spin (rad/s)", box.angular_velocity.norm(), 0.01);
              return std::string();
            });
}

// The deepest two bodies may overlap at a step's start: 5 mm, or a tenth of the thinner one's
// thinnest size (a plane's is unbounded).
std::string sinks_within(const physics::World& world) {
  auto thinnest = [&](int body) {
    return body < 0 ? std::numeric_limits<double>::infinity() : 2 * physics::thinnest_half_size(world.bodies()[body].shape);
  };
  for (const physics::ContactRecord& contact : world.record().contacts) {
    const double limit = std::min(0.005, 0.1 * std::min(thinnest(contact.body_a), thinnest(contact.body_b)));
    if (contact.penetration > limit) {
      std::ostringstream what;
      what << "bodies " << contact.body_a << " and " << contact.body_b << " overlap (m)";
      return breach_text(what.str().c_str(), contact.penetration, limit);
    }
  }
  return std::string();
}

// A box of any proportions (from a tile to a rod) dropped from up to 2 m, turned any way and
// spinning, onto the ground or a static box turned any way: it lands on an edge or a corner, rocks
// and slaps down on a face. The default restitution and friction.
std::string dropped_box(Draw& draw) {
  std::ostringstream text;
  text << "[scene]\ntitle = \"dropped box\"\nduration = 3.0\n";
  const bool on_box = draw.coin();
  const double floor = on_box ? 0.5 : 0;
  if (on_box)
    text << "[[body]]\nname = \"floor\"\nshape = \"box\"\nstatic = true\nsize = [8, 1, 8]\nrotation = [0, "
         << SceneText::number(draw.uniform(0, 90)) << ", 0]\n";
  else
    text << "[[body]]\nname = \"floor\"\nshape = \"plane\"\n";
  const Vec3 size = draw.vector(0.05, 1.2);
  const double mass = draw.uniform(0.1, 20), x = draw.uniform(-1, 1), lift = draw.uniform(0.05, 2), z = draw.uniform(-1, 1);
  const Vec3 degrees = draw.vector(0, 360);
  text << "[[body]]\nname = \"box\"\nshape = \"box\"\nsize = " << SceneText::vector(size) << "\nmass = "
       << SceneText::number(mass) << "\nposition = " << SceneText::vector(Vec3(x, floor + size.norm() / 2 + lift, z))
       << "\nrotation = " << SceneText::vector(degrees)
       << "\nangular_velocity = " << SceneText::vector(vector_of_length(draw, 0, 6)) << "\n";
  return text.str();
}

// A row of three to eight dominoes of any thickness, height and spacing, the first pushed over
// (turning about its front edge): each falls on the next, and the last slaps down on the ground.
std::string domino_run(Draw& draw) {
  std::ostringstream text;
  const int count = draw.integer(3, 8);
  const double thickness = draw.uniform(0.04, 0.12), height = draw.uniform(0.25, 0.6), width = draw.uniform(0.12, 0.3);
  const double spacing = thickness + draw.uniform(0.3, 0.7) * height, mass = draw.uniform(0.1, 1);
  const double spin = draw.uniform(1, 5);  // rad/s, forwards (about -z)
  text << "[scene]\ntitle = \"domino run\"\nduration = " << SceneText::number(1.0 + 0.4 * count)
       << "\n[[body]]\nname = \"ground\"\nshape = \"plane\"\n";
  for (int i = 0; i < count; ++i) {
    // The first turns about its front bottom edge: v = w x (centre - edge).
    const Vec3 w = i == 0 ? Vec3(0, 0, -spin) : Vec3::Zero();
    const Vec3 v = w.cross(Vec3(-thickness / 2, height / 2, 0));
    text << "[[body]]\nname = \"d" << i << "\"\nshape = \"box\"\nsize = " << SceneText::vector(Vec3(thickness, height, width))
         << "\nmass = " << SceneText::number(mass) << "\nposition = " << SceneText::vector(Vec3(i * spacing, height / 2, 0))
         << "\nvelocity = " << SceneText::vector(v) << "\nangular_velocity = " << SceneText::vector(w) << "\n";
  }
  return text.str();
}

TEST(ImpactLaws, AFallingBoxNeverSinksFurtherThanAFrameShows) {
  check_law("dropped-box", 60, dropped_box,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>&) { return sinks_within(world); });
}

// Each domino falls on the next and the last bounces off the ground under the one on it: a squeeze
// of moving bodies, which the stiffest contacts (physics/README.md, "How many sub-steps") keep
// within the limit.
TEST(ImpactLaws, DominoesNeverSinkFurtherThanAFrameShows) {
  check_law("domino-run", 40, domino_run,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>&) { return sinks_within(world); });
}

// As GeneratedLaws.ASeedIsTheSameSceneWhateverTheCompiler, for these generators.
TEST(ImpactLaws, ASeedIsTheSameSceneWhateverTheCompiler) {
  EXPECT_EQ(scenes_hash("thrown-at-a-surface", thrown_at_a_surface), 0xb4b76883686a2280ull);
  EXPECT_EQ(scenes_hash("jointed-impact", jointed_impact), 0x118ecea6956f26dcull);
  EXPECT_EQ(scenes_hash("flat-landing", flat_landing), 0x99a300c4ae853500ull);
  EXPECT_EQ(scenes_hash("dropped-box", dropped_box), 0x60e9500a1cb4bda8ull);
  EXPECT_EQ(scenes_hash("domino-run", domino_run), 0x9a15b24bd9f0b70aull);
}

}  // namespace
}  // namespace impulse::demos
