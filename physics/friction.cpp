#include "physics/friction.h"

#include "physics/normal_impulse.h"

namespace impulse::physics {

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
