// Small worlds that the physics tests share.
#pragma once
#include "physics/world.h"

#include <algorithm>
#include <vector>

namespace impulse::physics::test {

inline int add_ground(World& world, Real restitution = 0, Real friction = 0.5) {
  BodyDef ground;
  ground.name = "ground";
  ground.shape = Shape::plane(Vec3::UnitY(), 0);
  ground.material = {restitution, friction};
  return world.add_body(ground);
}

inline int add_sphere(World& world, const Vec3& position, Real radius, Real mass, const Vec3& velocity = Vec3::Zero(),
                      Material material = {}) {
  BodyDef def;
  def.name = "sphere";
  def.shape = Shape::sphere(radius);
  def.mass = mass;
  def.position = position;
  def.velocity = velocity;
  def.material = material;
  return world.add_body(def);
}

inline WorldSettings without_gravity(ResponseMethod method = ResponseMethod::impulse) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.method = method;
  return settings;
}

// The speed of a body's fastest point, at most: |v| + |w| r, r its bounding radius.
inline Real point_speed(const Body& body) { return body.velocity.norm() + body.angular_velocity.norm() * bounding_radius(body.shape); }

// Steps `world` on until `until_step` and returns the fastest point_speed of any moving body from
// `from_step` on (steps counted from 1).
inline Real fastest_from(World& world, int from_step, int until_step) {
  Real fastest = 0;
  for (int step = 1; step <= until_step; ++step) {
    world.step();
    if (step < from_step) continue;
    for (const Body& body : world.bodies())
      if (!body.is_static()) fastest = std::max(fastest, point_speed(body));
  }
  return fastest;
}

// Two unit boxes recorded in the heap of boxes at 30 s (mu 0.5, e 0.5), with their velocities, on
// the two boxes under them, made still. The upper one lies on the lower, standing on one edge of
// its face; the lower stands on two points of an edge of its own support, 0.6 mm above its other
// support. Cutting each step's clipped points to four from the deepest one, the upper box rocked
// onto its other edge and was thrown back, at 1-11 cm/s for a minute; Box3D stops them within a
// second. Returns the two moving boxes, upper first.
inline std::vector<int> add_rocking_boxes(World& world) {
  struct Recorded {
    Vec3 position;
    Quat orientation;  // w, x, y, z
    Vec3 velocity, angular_velocity;
    bool moves;
  };
  const Recorded boxes[] = {
      {{2.3191686619049601, 4.4994847841853938, -6.176230234612178},
       {0.61812044265754562, -0.35888904856218456, -0.34950978668310967, 0.60577939730870423},
       {-0.03055826885571155, -0.0036802363683349627, -0.018098912796909509},
       {-0.038357562999680843, -0.00039911865699238027, 0.06507403972740225}, true},
      {{1.8883365407103743, 3.5042127048054814, -6.3985654749851424},
       {-0.6808522825131561, 0.68804867890782007, 0.17309677110356342, 0.18184249416280465},
       {0.00084823423130562386, -0.0011547919930352301, 0.00064926870359496283},
       {-0.00050297861583570313, -0.0015325280545705365, -0.003024350554673334}, true},
      {{2.4960008257704671, 2.4999504223972751, -5.9177948961162912},
       {0.38859292013805308, -0.0070638916704619725, -0.92138129880426534, 0.0014649460105794791}, Vec3::Zero(), Vec3::Zero(), false},
      {{1.5187420205758144, 2.5057147310796029, -6.7667752459973469},
       {0.28214844999139033, 0.65502578520188925, 0.64578815807446244, 0.27256398841170765}, Vec3::Zero(), Vec3::Zero(), false},
  };
  std::vector<int> moving;
  for (const Recorded& r : boxes) {
    BodyDef def;
    def.shape = Shape::box(Vec3::Constant(0.5));
    def.is_static = !r.moves;
    def.mass = 1;
    def.material = {0.5, 0.5};
    def.position = r.position;
    def.orientation = r.orientation;
    def.velocity = r.velocity;
    def.angular_velocity = r.angular_velocity;
    const int body = world.add_body(def);
    if (r.moves) moving.push_back(body);
  }
  return moving;
}

inline Vec3 linear_momentum(const World& world) {
  Vec3 p = Vec3::Zero();
  for (const Body& b : world.bodies()) p += b.mass * b.velocity;
  return p;
}

}  // namespace impulse::physics::test

namespace impulse::physics::test {

inline int add_box(World& world, const Vec3& position, const Vec3& half_extents, Real mass, const Quat& orientation = Quat::Identity(),
                   const Vec3& velocity = Vec3::Zero(), Material material = {}) {
  BodyDef def;
  def.name = "box";
  def.shape = Shape::box(half_extents);
  def.mass = mass;
  def.position = position;
  def.orientation = orientation;
  def.velocity = velocity;
  def.material = material;
  return world.add_body(def);
}

// The benchmark's ground (../shared/bench/SCENES.md): a static box 200 x 1 x 200 m, top at y = 0.
inline int add_ground_box(World& world, Material material = {0, 0.6}) {
  BodyDef def;
  def.name = "ground";
  def.shape = Shape::box(Vec3(100, 0.5, 100));
  def.is_static = true;
  def.position = Vec3(0, -0.5, 0);
  def.material = material;
  return world.add_body(def);
}

inline Vec3 angular_momentum_about_origin(const World& world) {
  Vec3 l = Vec3::Zero();
  for (const Body& b : world.bodies())
    if (!b.is_static()) l += b.position.cross(b.mass * b.velocity) + b.inertia_world() * b.angular_velocity;
  return l;
}

}  // namespace impulse::physics::test
