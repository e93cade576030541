// Bodies and contacts for the narrow phase's tests (collide_box_test.cpp, collide_box_box_test.cpp).
#pragma once
#include "physics/collide.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace impulse::physics::test {

inline constexpr Real kMargin = 0.02;

inline constexpr Real kTol = 1e-9;

inline Body make(const Shape& shape, const Vec3& position, const Quat& orientation = Quat::Identity(), bool is_static = false) {
  BodyDef def;
  def.shape = shape;
  def.position = position;
  def.orientation = orientation;
  def.is_static = is_static;
  return make_body(def);
}

inline Body unit_box(const Vec3& position, const Quat& orientation = Quat::Identity()) {
  return make(Shape::box(Vec3(0.5, 0.5, 0.5)), position, orientation);
}

inline Quat about(const Vec3& axis, Real degrees) { return Quat(Eigen::AngleAxis<Real>(degrees * std::numbers::pi / 180, axis.normalized())); }

inline std::vector<Contact> contacts(const Body& a, const Body& b, Real margin = kMargin) {
  std::vector<Contact> out;
  const int n = collide(a, 0, b, 1, margin, out);
  EXPECT_EQ(n, int(out.size()));
  return out;
}

inline std::vector<uint32_t> features(const std::vector<Contact>& cs) {
  std::vector<uint32_t> f;
  for (const Contact& c : cs) f.push_back(c.feature);
  return f;
}

inline void expect_near(const Vec3& actual, const Vec3& expected, Real tol, const char* what) {
  EXPECT_LT((actual - expected).norm(), tol) << what << ": got " << actual.transpose() << ", want " << expected.transpose();
}

// True when p (projected on the y = 0 plane) lies inside the box's footprint, grown by tol.
inline bool in_footprint(const Body& box, const Vec3& p, Real tol) {
  Vec3 local = box.orientation.conjugate() * (p - box.position);
  return std::abs(local.x()) <= box.shape.half_extents.x() + tol && std::abs(local.z()) <= box.shape.half_extents.z() + tol;
}

}  // namespace impulse::physics::test
