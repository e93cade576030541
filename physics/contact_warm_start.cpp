// The warm start stage of the default method's sub-steps (soft_step.h): last sub-step's impulses
// (after prepare(), last step's, found again by pair and feature) applied again, two manifolds side
// by side (contact_lanes.h).
#include "physics/contact_solver.h"

namespace impulse::physics {

// Last sub-step's impulses, applied again. The points share the normal: one sum of their
// impulses, added to each body once with friction's.
void ContactSolver::warm_start_manifolds(int place, SolverBodies& solver_bodies) const {
  std::vector<BodyState>& states = solver_bodies.states;
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
    const Vec3 dv_a = sa.inv_mass * linear_l, dw_a = lane(turn_a, l);
    const Vec3 dv_b = -(sb.inv_mass * linear_l), dw_b = -lane(turn_b, l);
    add_velocity(sa, dv_a, dw_a);
    add_velocity(sb, dv_b, dw_b);
    // The bounce tells a load from an approach by these (contact_bounce.cpp); a still body's stay 0.
    if (sa.inv_mass != 0) solver_bodies.warm[size_t(block.a[l])].dv += dv_a, solver_bodies.warm[size_t(block.a[l])].dw += dw_a;
    if (sb.inv_mass != 0) solver_bodies.warm[size_t(block.b[l])].dv += dv_b, solver_bodies.warm[size_t(block.b[l])].dw += dw_b;
  }
}

}  // namespace impulse::physics
