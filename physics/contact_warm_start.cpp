// The warm start stage of the default method's sub-steps (soft_step.h): last sub-step's impulses
// (after prepare(), last step's, found again by pair and feature) applied again, two manifolds side
// by side (contact_lanes.h).
#include "physics/contact_solver.h"

namespace impulse::physics {

// Last sub-step's impulses, applied again. The points share the normal: one sum of their
// impulses, added to each body once with friction's.
void ContactSolver::warm_start_manifolds(int place, std::vector<BodyState>& states) const {
  const ManifoldLanes& block = lanes_[lane_of_place_[place].block];
  const Real2 j1 = block.tangent_impulse1, j2 = block.tangent_impulse2, twist = block.twist_impulse;
  Real2 normal_sum = splat(0);
  V3 turn_a = j1 * block.turn_a1 + j2 * block.turn_a2 + twist * block.twist_a;
  V3 turn_b = j1 * block.turn_b1 + j2 * block.turn_b2 + twist * block.twist_b;
  for (int i = 0; i < block.points; ++i) {
    const PointLanes& p = lane_points_[block.first_point + i];
    normal_sum = normal_sum + p.normal_impulse;
    turn_a = turn_a + p.normal_impulse * p.angular_a;
    turn_b = turn_b + p.normal_impulse * p.angular_b;
  }
  const V3 linear = normal_sum * block.normal + j1 * block.tangent1 + j2 * block.tangent2;
  for (int l = 0; l < 2; ++l) {
    BodyState& sa = states[block.a[l]];
    BodyState& sb = states[block.b[l]];
    const Vec3 linear_l = lane(linear, l);
    add_velocity(sa, sa.inv_mass * linear_l, lane(turn_a, l));
    add_velocity(sb, -(sb.inv_mass * linear_l), -lane(turn_b, l));
  }
}

}  // namespace impulse::physics
