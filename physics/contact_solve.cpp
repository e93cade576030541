// The solve stage of the default method's sub-steps (soft_step.h), and the relax stage, which is
// the same solve without the position bias (Box2D v3 and Box3D run one function for both): the
// normal rows (normal_impulse.h) and friction rows (friction.h) of two manifolds side by side
// (contact_lanes.h). Branches become lane-wise selections; the bits are those of solving the two
// manifolds one after the other. In the biased solve a manifold that meets fast enough bounces
// instead (contact_bounce.cpp).
#include "physics/contact_solver.h"
#include "physics/friction.h"
#include "physics/normal_impulse.h"
#include "physics/pair_points.h"

namespace impulse::physics {

namespace {
// The Gauss-Seidel passes over a pair's points where the pivoting did not settle: until a pass
// changes no point's normal velocity by more than this, or at most this many.
constexpr Real kTolerance = 1e-5;  // m/s
constexpr int kMostPasses = 16;

// At most `most` Gauss-Seidel passes over the points of the lanes `by_passes`, forwards then
// backwards (or the other way round), until one changes no normal velocity by more than
// kTolerance; apply(k, change) adds to point k's impulse. Out of line: a pair seldom needs it.
template <int N, class Apply>
[[gnu::noinline]] void gauss_seidel_passes(const Real2 (&coupling)[4][4], const NormalRow (&rows)[N], Mask2 by_passes, bool backwards, int most,
                                           Real2 (&vn)[N], const Real2 (&impulse)[N], Apply& apply) {
  for (int pass = 0; pass < most; ++pass) {
    Real2 vn_before[N];
    for (int k = 0; k < N; ++k) vn_before[k] = vn[k];
    for (int order = 0; order < N; ++order) {
      const int k = (pass % 2 == 1) != backwards ? N - 1 - order : order;
      const Real2 applied = select(by_passes, clamped_normal_impulse(rows[k], impulse[k], vn[k]), impulse[k]) - impulse[k];
      apply(k, applied);
      for (int j = 0; j < N; ++j) vn[j] = vn[j] + coupling[j][k] * applied;
    }
    Mask2 moving = (vn[0] - vn_before[0] > kTolerance) | (vn_before[0] - vn[0] > kTolerance);
    for (int k = 1; k < N; ++k) moving = moving | (vn[k] - vn_before[k] > kTolerance) | (vn_before[k] - vn[k] > kTolerance);
    if (!any(moving)) break;
  }
}

}  // namespace

bool ContactSolver::solve_manifolds(int place, int width, SolverBodies& solver_bodies, Real inv_h, bool use_bias) {
  ManifoldLanes& block = lanes_[lane_of_place_[place].block];
  // A manifold that bounces is answered by its bounce alone in this solve (restitution.h); the
  // bounce's impulses go to the lane's totals.
  Mask2 solved = {0, 0};
  bool bounced = false;
  for (int l = 0; l < width; ++l) {
    // A pressed pair that cannot bounce (a resting stack's) is known from the lanes alone.
    if (use_bias && (block.can_bounce || unpressed(block, l)) && bounce_lane(place + l, solver_bodies, 1 / inv_h)) bounced = true;
    else solved[l] = -1;
  }
  if (!any(solved)) return bounced;
  // The points and the pass known to the compiler: the rows stay in registers.
  using Solve = void (ContactSolver::*)(ManifoldLanes&, Mask2, SolverBodies&, Real);
  static constexpr Solve kSolves[4][2] = {{&ContactSolver::solve_lanes<1, false>, &ContactSolver::solve_lanes<1, true>},
                                          {&ContactSolver::solve_lanes<2, false>, &ContactSolver::solve_lanes<2, true>},
                                          {&ContactSolver::solve_lanes<3, false>, &ContactSolver::solve_lanes<3, true>},
                                          {&ContactSolver::solve_lanes<4, false>, &ContactSolver::solve_lanes<4, true>}};
  (this->*kSolves[block.points - 1][use_bias])(block, solved, solver_bodies, inv_h);
  return bounced;
}

// The lanes `solved` of a block of manifolds with N points each, which move no body in common.
//
// Normal rows (normal_impulse.h): the pair's points solved together, exactly (pair_points.h: the
// biased solve's compliant rows, the relax solve's rigid ones), so that no point of a face gets
// more than its share whatever the order (one pass of Gauss-Seidel leaves the first point more: a
// box that lands flat starts to turn, a wall of boxes one box thick sways). The points of one pair
// see each other only through the coupling matrix, so their normal velocities move alone and the
// bodies get the sum afterwards. Where the pivoting does not settle (rounding at a point that
// neither pushes nor separates), Gauss-Seidel passes point after point until they agree, forwards
// and backwards in turn from one sub-step to the next. Then the friction rows (friction.h) at the
// points' centroid.
template <int N, bool UseBias>
IMPULSE_LANES_KERNEL void ContactSolver::solve_lanes(ManifoldLanes& block, Mask2 solved, SolverBodies& solver_bodies, Real inv_h) {
  std::vector<BodyState>& states = solver_bodies.states;
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
  // A corner against a face is measured along the face's normal as it is now, n' (n turned with
  // the face's body), so that a corner sliding along a turning face is measured from that face:
  //   s = n'.(dp_a - dp_b + dq_a r_a - dq_b r_b - (r_a - r_b)) + separation
  //     = separation_now() along n' + (r_a - r_b).(n - n')   (adjusted_separation is along n)
  // The points share the normal: n'.(dq r) = (dq^-1 n').r turns it back once per body instead of
  // turning every anchor. A sphere's surface stays put as it turns; a still body's dq is 1.
  V3 normal_now = normal;
  Real2 tilt = splat(0);
  if (any(block.face_of != 0)) {
    normal_now = select(block.face_of == 2, rotate(dq_b, normal), select(block.face_of == 1, rotate(dq_a, normal), normal));
    tilt = dot(block.centres, normal - normal_now);
  }
  auto turned_back = [&](const Q4& dq, Real2 turns) {
    const Mask2 mask = turns != 0;
    return any(mask) ? select(mask, rotate(conjugate(dq), normal_now), normal_now) : normal_now;
  };
  const V3 normal_in_a = turned_back(dq_a, block.turns_a);
  const V3 normal_in_b = turned_back(dq_b, block.turns_b);
  const Real2 moved = dot(dp, normal_now) + tilt;
  const Real2 dv_n = dot(va - vb, normal);
  const Real2 max_push = splat(-settings_.max_push_velocity);
  Real2 vn[N], impulse[N];
  NormalRow rows[N];
  for (int i = 0; i < N; ++i) {
    const PointLanes& p = points[i];
    const Real2 separation = separation_now(moved, normal_in_a, normal_in_b, p.anchor_a, p.anchor_b, p.adjusted_separation);
    vn[i] = dv_n + dot(wa, p.ra_cross_n) - dot(wb, p.rb_cross_n);
    impulse[i] = p.normal_impulse;
    rows[i] = soft_normal_row<UseBias>(separation, p.normal_mass, softness_, inv_h, max_push);
  }
  Real2 applied_sum = splat(0);
  V3 turn_a{applied_sum, applied_sum, applied_sum}, turn_b = turn_a;
  auto apply = [&](int k, Real2 applied) {
    impulse[k] = impulse[k] + applied;
    applied_sum = applied_sum + applied;
    turn_a = turn_a + applied * points[k].angular_a;
    turn_b = turn_b + applied * points[k].angular_b;
  };
  // A pair's points at once (pair_points.h); Gauss-Seidel passes where that did not settle.
  Mask2 by_passes = solved;
  if constexpr (N > 1) {
    const Real2 share = splat(UseBias ? soft_share(softness_) : 0);
    PairRowsIn in[N];
    Real2 solution[N];
    for (int i = 0; i < N; ++i) {
      const Real2 compliance = row_compliance(select(rows[i].touching, share, splat(0)), block.coupling[i][i]);
      in[i] = {rows[i].bias, compliance, solved & (rows[i].mass > 0), rows[i].touching};
      solution[i] = impulse[i];
    }
    by_passes = solved & ~solve_pair_points<N>(block.coupling, block.factors[UseBias], in, vn, solution);
    for (int k = 0; k < N; ++k) {
      const Real2 applied = solution[k] - impulse[k];
      apply(k, applied);
      if (any(by_passes))
        for (int j = 0; j < N; ++j) vn[j] = vn[j] + block.coupling[j][k] * applied;
    }
  }
  if (any(by_passes)) gauss_seidel_passes<N>(block.coupling, rows, by_passes, backwards_, N > 1 ? kMostPasses : 1, vn, impulse, apply);
  Real2 normal_sum = splat(0);
  for (int i = 0; i < N; ++i) normal_sum = normal_sum + impulse[i];
  const V3 linear = applied_sum * normal;
  va = va + inv_mass_a * linear;
  wa = wa + turn_a;
  vb = vb - inv_mass_b * linear;
  wb = wb - turn_b;

  Real2 j1 = block.tangent_impulse1, j2 = block.tangent_impulse2, twist = block.twist_impulse;
  if (any(block.friction != 0))
    solve_friction_lanes<UseBias>(block, normal_sum, inv_mass_a, inv_mass_b, va, wa, vb, wb, j1, j2, twist);
  if constexpr (!UseBias) {
    if (any(block.rolling_radius > 0)) resist_rolling(block, solved, normal_sum, sa, sb, solver_bodies.inertia, wa, wb);
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
