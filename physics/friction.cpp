#include "physics/friction.h"

#include "physics/normal_impulse.h"

namespace impulse::physics {

using Vec2 = Eigen::Matrix<Real, 2, 1>;
using Mat2 = Eigen::Matrix<Real, 2, 2>;

// Inside, x = j0 - K^-1 v; else on the rim, x = (K + l I)^-1 b with b = K j0 - v and l >= 0 the
// root of 1/limit - 1/|x(l)| (Newton's method from l = 0, which approaches it from below without
// overshooting: More and Sorensen's trust-region step).
Vec2 least_energy_in_disc(const Mat2& k, const Vec2& v, const Vec2& j0, Real limit) {
  const Vec2 b = k * j0 - v;
  const Real det = k.determinant();
  if (!(det > 0)) return Vec2::Zero();
  Vec2 x = Vec2(k(1, 1) * b[0] - k(0, 1) * b[1], k(0, 0) * b[1] - k(1, 0) * b[0]) / det;
  if (x.squaredNorm() <= limit * limit) return x;
  if (limit <= 0) return Vec2::Zero();
  Real l = 0;
  for (int i = 0; i < 50; ++i) {
    const Mat2 shifted = k + l * Mat2::Identity();
    const Real d = shifted.determinant();
    x = Vec2(shifted(1, 1) * b[0] - shifted(0, 1) * b[1], shifted(0, 0) * b[1] - shifted(1, 0) * b[0]) / d;
    const Real length = x.norm();
    // dx/dl = -(K + l I)^-1 x; d(1/|x|)/dl = -x . dx/dl / |x|^3.
    const Vec2 dx = -Vec2(shifted(1, 1) * x[0] - shifted(0, 1) * x[1], shifted(0, 0) * x[1] - shifted(1, 0) * x[0]) / d;
    const Real step = (1 / limit - 1 / length) / (-x.dot(dx) / (length * length * length));
    if (!(step > 1e-15 * (1 + l))) break;
    l += step;
  }
  return x * std::min(Real(1), limit / x.norm());
}

void impact_friction(const ManifoldLanes& block, int l, Real bounce, Vec2& impulse, BodyState& sa, BodyState& sb) {
  const Vec3 t1 = lane(block.tangent1, l), t2 = lane(block.tangent2, l);
  const Vec3 ra_t1 = lane(block.ra_cross_t1, l), ra_t2 = lane(block.ra_cross_t2, l);
  const Vec3 rb_t1 = lane(block.rb_cross_t1, l), rb_t2 = lane(block.rb_cross_t2, l);
  const Vec3 turn_a1 = lane(block.turn_a1, l), turn_a2 = lane(block.turn_a2, l);
  const Vec3 turn_b1 = lane(block.turn_b1, l), turn_b2 = lane(block.turn_b2, l);
  // The tangents' effective mass matrix: eq. 13's denominator along each, and between them.
  Mat2 k;
  k(0, 0) = safe_inverse(block.tangent_mass1[l]);
  k(1, 1) = safe_inverse(block.tangent_mass2[l]);
  k(0, 1) = k(1, 0) = (sa.inv_mass + sb.inv_mass) * t1.dot(t2) + ra_t1.dot(turn_a2) + rb_t1.dot(turn_b2);
  const Vec3 dv = sa.v - sb.v;
  const Vec2 v(dv.dot(t1) + sa.w.dot(ra_t1) - sb.w.dot(rb_t1), dv.dot(t2) + sa.w.dot(ra_t2) - sb.w.dot(rb_t2));
  const Vec2 j = least_energy_in_disc(k, v, impulse, block.friction[l] * bounce) - impulse;
  impulse += j;
  add_velocity(sa, sa.inv_mass * (j[0] * t1 + j[1] * t2), j[0] * turn_a1 + j[1] * turn_a2);
  add_velocity(sb, -(sb.inv_mass * (j[0] * t1 + j[1] * t2)), -(j[0] * turn_b1 + j[1] * turn_b2));
}

void resist_rolling(const ManifoldLanes& block, Mask2 solved, Real2 normal_sum, const BodyState* const sa[2], const BodyState* const sb[2],
                    const std::vector<BodyInertia>& inertia, V3& wa, V3& wb) {
  for (int l = 0; l < 2; ++l) {
    if (!solved[l] || block.rolling_radius[l] <= 0) continue;
    const Mat3& inv_a = inertia[block.a[l]].inv_inertia;
    const Mat3& inv_b = inertia[block.b[l]].inv_inertia;
    const Vec3 t1 = lane(block.tangent1, l), t2 = lane(block.tangent2, l);
    Vec3 w_a = lane(wa, l), w_b = lane(wb, l);
    const Vec3 turning = w_a - w_b;
    Real j1 = -turning.dot(t1) * safe_inverse(t1.dot((inv_a + inv_b) * t1));
    Real j2 = -turning.dot(t2) * safe_inverse(t2.dot((inv_a + inv_b) * t2));
    clamp_to_coulomb_disc(j1, j2, block.rolling_radius[l] * normal_sum[l]);
    const Vec3 impulse = j1 * t1 + j2 * t2;
    if (sa[l]->inv_mass != 0) w_a += inv_a * impulse;
    if (sb[l]->inv_mass != 0) w_b -= inv_b * impulse;
    set_lane(wa, l, w_a);
    set_lane(wb, l, w_b);
  }
}

}  // namespace impulse::physics
