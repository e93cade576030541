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

inline Vec3 linear_momentum(const World& world) {
  Vec3 p = Vec3::Zero();
  for (const Body& b : world.bodies()) p += b.mass * b.velocity;
  return p;
}

}  // namespace impulse::physics::test
