// Bodies placed by hand for the narrow phase's tests, and their contacts seen from the first.
#pragma once
#include "physics/body.h"
#include "physics/collide.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace impulse::physics::placing {

inline Body placed(const Shape& shape, const Vec3& position, const Quat& orientation = Quat::Identity()) {
  BodyDef def;
  def.shape = shape;
  def.position = position;
  def.orientation = orientation;
  def.is_static = shape.type == ShapeType::plane;
  return make_body(def);
}

inline Quat about(const Vec3& axis, double degrees) {
  return Quat(Eigen::AngleAxis<Real>(degrees * std::numbers::pi / 180, axis.normalized()));
}

// The normal as the way `a` leaves `b`, whichever collide() made A.
inline std::vector<Contact> contacts(const Body& a, const Body& b, Real margin = 0.01) {
  std::vector<Contact> out;
  collide(a, 0, b, 1, margin, out);
  for (Contact& c : out)
    if (c.body_a != 0) c.normal = -c.normal;
  return out;
}

}  // namespace impulse::physics::placing
