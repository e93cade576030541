// Scalar and vector types of the engine. One place to switch precision.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace impulse::physics {

using Real = double;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Quat = Eigen::Quaternion<Real>;

inline bool is_finite(const Vec3& v) { return v.allFinite(); }
inline bool is_finite(const Quat& q) { return q.coeffs().allFinite(); }

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
