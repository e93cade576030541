// The sweeps' work, two manifolds side by side (lanes.h): the blocks' data packed lane by lane
// from the prepared manifolds and back, the warm start, and the solve of the normal and friction
// rows. The rest of the contact solver is in contact_solver.cpp.
#include "physics/contact_solver.h"

namespace impulse::physics {

// The block of a step's manifold, its lane given the manifold's bodies (and emptied first, with
// its second lane left still, by the block's first manifold).
ManifoldLanes& ContactSolver::begin_lanes(int step, const ManifoldConstraint& m) {
  const auto [index, l] = lane_of_step_[step];
  ManifoldLanes& block = lanes_[index];
  if (l == 0) {
    const int first_point = block.first_point;
    block = ManifoldLanes{};
    block.points = m.count;
    block.first_point = first_point;
    block.a[1] = block.b[1] = world_slot_;
    for (int i = 0; i < m.count; ++i) lane_points_[first_point + i] = PointLanes{};
  }
  block.a[l] = m.a;
  block.b[l] = m.b;
  return block;
}

// The rest of a prepared manifold's lane (prepare_manifold() wrote its friction rows): the shared
// normal and tangents, the warm start, and the points.
void ContactSolver::fill_lanes(int step, const ManifoldConstraint& m) {
  const auto [index, l] = lane_of_step_[step];
  ManifoldLanes& block = lanes_[index];
  set_lane(block.normal, l, m.normal);
  set_lane(block.tangent1, l, m.tangent1);
  set_lane(block.tangent2, l, m.tangent2);
  block.friction[l] = m.friction;
  block.tangent_impulse1[l] = m.tangent_impulse1;
  block.tangent_impulse2[l] = m.tangent_impulse2;
  block.twist_impulse[l] = m.twist_impulse;
  for (int i = 0; i < m.count; ++i) {
    const ContactConstraint& c = constraints_[m.first + i];
    PointLanes& p = lane_points_[block.first_point + i];
    set_lane(p.anchor_a, l, c.anchor_a);
    set_lane(p.anchor_b, l, c.anchor_b);
    set_lane(p.ra_cross_n, l, c.ra_cross_n);
    set_lane(p.rb_cross_n, l, c.rb_cross_n);
    set_lane(p.angular_a, l, c.angular_a);
    set_lane(p.angular_b, l, c.angular_b);
    p.adjusted_separation[l] = c.adjusted_separation;
    p.normal_mass[l] = c.normal_mass;
    p.normal_impulse[l] = c.normal_impulse;
  }
}

// The step's impulses, from its lane back to its manifold and points: for the records, the loads
// and the next step's warm start.
void ContactSolver::copy_back(int step) {
  const auto [index, l] = lane_of_step_[step];
  const ManifoldLanes& block = lanes_[index];
  ManifoldConstraint& m = manifolds_[step];
  m.tangent_impulse1 = block.tangent_impulse1[l];
  m.tangent_impulse2 = block.tangent_impulse2[l];
  m.twist_impulse = block.twist_impulse[l];
  m.total_tangent_impulse1 = block.total_tangent_impulse1[l];
  m.total_tangent_impulse2 = block.total_tangent_impulse2[l];
  for (int i = 0; i < m.count; ++i) {
    constraints_[m.first + i].normal_impulse = lane_points_[block.first_point + i].normal_impulse[l];
    constraints_[m.first + i].total_normal_impulse = lane_points_[block.first_point + i].total_normal_impulse[l];
  }
}

void ContactSolver::warm_start_manifolds(int index, int, std::vector<BodyState>& states) const {
  warm_start_lanes(lanes_[lane_of_step_[index].block], states);
}

// Last sub-step's impulses, applied again. The points share the normal: one sum of their
// impulses, added to each body once with friction's.
void ContactSolver::warm_start_lanes(const ManifoldLanes& block, std::vector<BodyState>& states) const {
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

bool ContactSolver::solve_manifolds(int index, int width, std::vector<BodyState>& states, Real inv_h, bool use_bias) {
  ManifoldLanes& block = lanes_[lane_of_step_[index].block];
  // A manifold that bounces is answered by bounce() alone in this solve.
  Mask2 solved = {0, 0};
  bool bounced = false;
  for (int l = 0; l < width; ++l) {
    ManifoldConstraint& m = manifolds_[index + l];
    if (use_bias && block.can_bounce && bounce(index + l, states[m.a], states[m.b], 1 / inv_h)) bounced = true;
    else solved[l] = -1;
  }
  if (!any(solved)) return bounced;
  // The points, the direction and the pass known to the compiler: the rows stay in registers.
  using Solve = void (ContactSolver::*)(ManifoldLanes&, Mask2, std::vector<BodyState>&, Real);
  static constexpr Solve kSolves[4][2][2] = {
      {{&ContactSolver::solve_lanes<1, false, false>, &ContactSolver::solve_lanes<1, false, true>},
       {&ContactSolver::solve_lanes<1, true, false>, &ContactSolver::solve_lanes<1, true, true>}},
      {{&ContactSolver::solve_lanes<2, false, false>, &ContactSolver::solve_lanes<2, false, true>},
       {&ContactSolver::solve_lanes<2, true, false>, &ContactSolver::solve_lanes<2, true, true>}},
      {{&ContactSolver::solve_lanes<3, false, false>, &ContactSolver::solve_lanes<3, false, true>},
       {&ContactSolver::solve_lanes<3, true, false>, &ContactSolver::solve_lanes<3, true, true>}},
      {{&ContactSolver::solve_lanes<4, false, false>, &ContactSolver::solve_lanes<4, false, true>},
       {&ContactSolver::solve_lanes<4, true, false>, &ContactSolver::solve_lanes<4, true, true>}}};
  (this->*kSolves[block.points - 1][backwards_][use_bias])(block, solved, states, inv_h);
  return bounced;
}

// Rolling resistance, in the relax pass, for a sphere's one point: an angular impulse about the
// tangents against the bodies' relative turning, within the disc of radius c R N (a torque c R N
// over the sub-step: the rolling resistance coefficient c, as a rolling ball on a floor that gives
// a little meets, and so slows at c g / (1 + I / (m R^2))). Solved afresh each pass, not warm
// started: few manifolds have it, and each pass is one sub-step's worth.
void ContactSolver::resist_rolling(const ManifoldLanes& block, Mask2 solved, Real2 normal_sum, BodyState* const sa[2],
                                   BodyState* const sb[2], V3& wa, V3& wb) const {
  for (int l = 0; l < 2; ++l) {
    if (!solved[l] || block.rolling_radius[l] <= 0) continue;
    const Mat3& inv_a = sa[l]->inv_inertia;
    const Mat3& inv_b = sb[l]->inv_inertia;
    const Vec3 t1 = lane(block.tangent1, l), t2 = lane(block.tangent2, l);
    Vec3 w_a = lane(wa, l), w_b = lane(wb, l);
    const Vec3 turning = w_a - w_b;
    Real j1 = -turning.dot(t1) * safe_inverse(t1.dot((inv_a + inv_b) * t1));
    Real j2 = -turning.dot(t2) * safe_inverse(t2.dot((inv_a + inv_b) * t2));
    const Real limit = block.rolling_radius[l] * normal_sum[l];
    const Real length_squared = j1 * j1 + j2 * j2;
    if (length_squared > limit * limit) {
      const Real scale = limit / std::sqrt(length_squared);
      j1 *= scale;
      j2 *= scale;
    }
    const Vec3 impulse = j1 * t1 + j2 * t2;
    if (sa[l]->inv_mass != 0) w_a += inv_a * impulse;
    if (sb[l]->inv_mass != 0) w_b -= inv_b * impulse;
    set_lane(wa, l, w_a);
    set_lane(wb, l, w_b);
  }
}

// The lanes `solved` of a block of manifolds with N points each, which move no body in common.
//
// Normal rows: accumulated and clamped to push only; the target is "stop approaching" (restitution
// is bounce()'s), with a soft position correction in the biased solve. Gauss-Seidel point after
// point, as if each impulse were applied to the bodies at once; but the points of one pair see
// each other only through the coupling matrix, so the pass updates their normal velocities alone,
// and the bodies get the sum afterwards (the same arithmetic, without a chain through the bodies'
// velocities after every point). One pass, in turn forwards and backwards from one sub-step to
// the next: always forwards, the first point gets more than its share, and a wall of boxes one
// box thick (the 21-box pyramid) starts to sway.
//
// Friction: Coulomb friction at the points' centroid, within the disc of radius mu times their
// total normal impulse, and a twist about the normal within mu times that times the points'
// spread. Both passes hold the centroid's sliding velocity at zero with the full (hard) tangent
// mass: static friction has no position target, so a pair that rocks from a face onto an edge
// is not pulled back towards where it first touched (such a pull fed the rocking of resting
// heaps), and nothing leaks from the friction impulse in the biased pass (a soft friction let a
// heap slide apart at m/s). The twist is left to the relax pass: solved in the biased one too, a
// wall of boxes one box thick (the 21-box pyramid) swayed out of its plane.
template <int N, bool Backwards, bool UseBias>
void ContactSolver::solve_lanes(ManifoldLanes& block, Mask2 solved, std::vector<BodyState>& states, Real inv_h) {
  BodyState* sa[2] = {&states[block.a[0]], &states[block.a[1]]};
  BodyState* sb[2] = {&states[block.b[0]], &states[block.b[1]]};
  PointLanes* points = &lane_points_[block.first_point];
  V3 va = lanes(sa[0]->v, sa[1]->v), wa = lanes(sa[0]->w, sa[1]->w);
  V3 vb = lanes(sb[0]->v, sb[1]->v), wb = lanes(sb[0]->w, sb[1]->w);
  const Real2 inv_mass_a{sa[0]->inv_mass, sa[1]->inv_mass}, inv_mass_b{sb[0]->inv_mass, sb[1]->inv_mass};
  const V3 dp = lanes(sa[0]->dp, sa[1]->dp) - lanes(sb[0]->dp, sb[1]->dp);
  const Q4 dq_a = lanes(sa[0]->dq, sa[1]->dq), dq_b = lanes(sb[0]->dq, sb[1]->dq);
  const V3& normal = block.normal;

  // Each point's separation now (positions do not change during the passes) and normal velocity.
  // The points share the normal: n . (dq r) = (dq^-1 n) . r turns the normal back once per body
  // instead of turning every anchor. A sphere's surface stays put as it turns; a still body's dq is 1.
  auto turned_back = [&](const Q4& dq, Real2 turns) {
    const Mask2 mask = turns != 0;
    return any(mask) ? select(mask, rotate(conjugate(dq), normal), normal) : normal;
  };
  const V3 normal_in_a = turned_back(dq_a, block.turns_a);
  const V3 normal_in_b = turned_back(dq_b, block.turns_b);
  const Real2 moved = dot(dp, normal);
  const Real2 dv_n = dot(va - vb, normal);
  const Real2 max_push = splat(-settings_.max_push_velocity);
  // Row k's new impulse is max(rhs_k - mass_k vn_k, 0), with rhs = impulse - mass bias - leak impulse.
  Real2 vn[N], mass[N], rhs[N], impulse[N];
  for (int i = 0; i < N; ++i) {
    const PointLanes& p = points[i];
    const Real2 separation = moved + dot(normal_in_a, p.anchor_a) - dot(normal_in_b, p.anchor_b) + p.adjusted_separation;
    vn[i] = dv_n + dot(wa, p.ra_cross_n) - dot(wb, p.rb_cross_n);
    impulse[i] = p.normal_impulse;
    // Speculative (apart): may close the gap this sub-step, no further. The relax pass leaves it
    // be (mass 0): the next solve clamps it anyway, and slowing a body before it touches would
    // lose the speed it hits with.
    const Mask2 apart = separation > 0;
    if constexpr (UseBias) {
      const Real2 soft_bias = splat(softness_.bias_rate) * separation;
      const Real2 bias = select(apart, separation * inv_h, select(soft_bias < max_push, max_push, soft_bias));
      mass[i] = select(apart, p.normal_mass, p.normal_mass * splat(softness_.mass_scale));
      rhs[i] = impulse[i] - mass[i] * bias - select(apart, splat(0), splat(softness_.impulse_scale)) * impulse[i];
    } else {
      mass[i] = select(apart, splat(0), p.normal_mass);
      rhs[i] = impulse[i];
    }
  }
  Real2 applied_sum = splat(0);
  V3 turn_a{applied_sum, applied_sum, applied_sum}, turn_b = turn_a;
  for (int step = 0; step < N; ++step) {
    const int k = Backwards ? N - 1 - step : step;
    const Real2 new_impulse = max0(rhs[k] - mass[k] * vn[k]);
    const Real2 applied = new_impulse - impulse[k];
    impulse[k] = new_impulse;
    applied_sum = applied_sum + applied;
    turn_a = turn_a + applied * points[k].angular_a;
    turn_b = turn_b + applied * points[k].angular_b;
    for (int j = 0; j < N; ++j)
      if (j != k) vn[j] = vn[j] + block.coupling[j][k] * applied;
  }
  Real2 normal_sum = splat(0);
  for (int i = 0; i < N; ++i) normal_sum = normal_sum + impulse[i];
  const V3 linear = applied_sum * normal;
  va = va + inv_mass_a * linear;
  wa = wa + turn_a;
  vb = vb - inv_mass_b * linear;
  wb = wb - turn_b;

  // Friction, if either lane has any.
  Real2 j1 = block.tangent_impulse1, j2 = block.tangent_impulse2, twist = block.twist_impulse;
  if (any(block.friction != 0)) {
    const Real2 limit = block.friction * normal_sum;
    const V3 dv = va - vb;
    const Real2 v1 = dot(dv, block.tangent1) + dot(wa, block.ra_cross_t1) - dot(wb, block.rb_cross_t1);
    const Real2 v2 = dot(dv, block.tangent2) + dot(wa, block.ra_cross_t2) - dot(wb, block.rb_cross_t2);
    const Real2 old1 = j1, old2 = j2, old_twist = twist;
    j1 = old1 - block.tangent_mass1 * v1;
    j2 = old2 - block.tangent_mass2 * v2;
    // Within the Coulomb disc.
    const Real2 length_squared = j1 * j1 + j2 * j2;
    const Mask2 outside = length_squared > limit * limit;
    if (any(outside)) {
      const Real2 scale = select(outside, limit / sqrt(length_squared), splat(1));
      j1 = j1 * scale;
      j2 = j2 * scale;
    }
    if constexpr (!UseBias) {
      const Real2 twist_limit = limit * block.twist_radius;
      twist = select(block.twist_radius > 0, clamp(old_twist - block.twist_mass * dot(wa - wb, normal), -twist_limit, twist_limit), old_twist);
    }
    // Not pressed together (a speculative pair): no friction.
    const Mask2 unpressed = limit == 0;
    j1 = select(unpressed, splat(0), j1);
    j2 = select(unpressed, splat(0), j2);
    twist = select(unpressed, splat(0), twist);
    const Real2 applied1 = j1 - old1, applied2 = j2 - old2, applied_twist = twist - old_twist;
    const V3 linear_friction = applied1 * block.tangent1 + applied2 * block.tangent2;
    va = va + inv_mass_a * linear_friction;
    wa = wa + (applied1 * block.turn_a1 + applied2 * block.turn_a2 + applied_twist * block.twist_a);
    vb = vb - inv_mass_b * linear_friction;
    wb = wb - (applied1 * block.turn_b1 + applied2 * block.turn_b2 + applied_twist * block.twist_b);
  }

  if constexpr (!UseBias) {
    if (any(block.rolling_radius > 0)) resist_rolling(block, solved, normal_sum, sa, sb, wa, wb);
  }

  // Only the solved lanes: the other bounced, or is empty.
  for (int i = 0; i < N; ++i) points[i].normal_impulse = select(solved, impulse[i], points[i].normal_impulse);
  block.tangent_impulse1 = select(solved, j1, block.tangent_impulse1);
  block.tangent_impulse2 = select(solved, j2, block.tangent_impulse2);
  block.twist_impulse = select(solved, twist, block.twist_impulse);
  for (int l = 0; l < 2; ++l) {
    if (!solved[l]) continue;
    // A still body's state is not even written: the other thread may be reading it.
    if (sa[l]->inv_mass != 0) {
      sa[l]->v = lane(va, l);
      sa[l]->w = lane(wa, l);
    }
    if (sb[l]->inv_mass != 0) {
      sb[l]->v = lane(vb, l);
      sb[l]->w = lane(wb, l);
    }
  }
}

}  // namespace impulse::physics
