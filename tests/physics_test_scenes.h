// Small worlds that the physics tests share.
#pragma once
#include "physics/world.h"

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
