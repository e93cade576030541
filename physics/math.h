// Scalar and vector types of the engine. One place to switch precision.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace impulse::physics {

using Real = double;
constexpr Real kPi = Real(3.14159265358979323846);
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Quat = Eigen::Quaternion<Real>;

inline Real dot(const Vec3& a, const Vec3& b) { return a.dot(b); }  // as lanes.h's, for code written once for both
inline bool is_finite(const Vec3& v) { return v.allFinite(); }
inline bool is_finite(const Quat& q) { return q.coeffs().allFinite(); }

// q v q*, written out in scalars: v + w t + u x t with t = 2 u x v (u = q's vector part). Eigen's
// q * v compiles (GCC 12) into stores and wider reloads that stall store forwarding, and the
// solver rotates anchors in its innermost loops.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
  const Real ux = q.x(), uy = q.y(), uz = q.z(), w = q.w();
  const Real tx = 2 * (uy * v.z() - uz * v.y());
  const Real ty = 2 * (uz * v.x() - ux * v.z());
  const Real tz = 2 * (ux * v.y() - uy * v.x());
  return Vec3(v.x() + w * tx + (uy * tz - uz * ty), v.y() + w * ty + (uz * tx - ux * tz), v.z() + w * tz + (ux * ty - uy * tx));
}

// The matrix [r]x with [r]x v = r x v.
inline Mat3 skew(const Vec3& r) {
  Mat3 m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

// Two unit vectors that with n form an orthonormal basis (Duff et al., "Building an Orthonormal
// Basis, Revisited"). Used for the two friction directions.
inline void tangent_basis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Real sign = std::copysign(Real(1), n.z());
  const Real a = Real(-1) / (sign + n.z());
  const Real b = n.x() * n.y() * a;
  t1 = Vec3(1 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  t2 = Vec3(b, sign + n.y() * n.y() * a, -n.y());
}

}  // namespace impulse::physics
