// The bounce stage of the default method's sub-steps (soft_step.h; restitution.h has its kernels):
// in the sub-step in which a manifold's points meet faster than the threshold, answered at the
// moment of contact, listing 1's way with its equations corrected:
//   1. the hits: which points meet within the sub-step, when, and at what normal velocity (the
//      bodies' own: the slower of it with and without what this sub-step's warm start added);
//   2. the pair at the moment the first meets: the lever arms to where the surfaces meet, from
//      which the manifold's rows are written again for the rest of the step;
//   3. the normal impulses of all the points that meet, together, to e times the velocity at which
//      they meet (eq. 5, eq. 13 with 1 + e), with every joint on either body held;
//   4. then friction: the manifold's own friction rows (friction.h), whose Coulomb disc counts the
//      bounce's normal impulses, to stop the sliding where the surfaces meet or to slide through the
//      whole impact at mu times the bounce, whichever Coulomb allows;
//   5. every body the impact moved moves on from the moment of contact, as the exact motion does:
//      the impulses act on the bodies as they are then (moved on by their old velocities), which
//      are then moved back to the sub-step's start along their new ones.
// Momentum and angular momentum are kept exactly (every impulse acts on both bodies at one point);
// each of 3 and 4 takes energy away or, at e = 1 and without friction, keeps it.
#include "physics/contact_solver.h"
#include "physics/friction.h"
#include "physics/joint_solver.h"
#include "physics/normal_impulse.h"
#include "physics/restitution.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace impulse::physics {

namespace {

// The impact's rows are iterated until a pass changes no impulse by more than this share of the
// largest, or at most this often: the points of a face that lands flat, or a hit passing through
// a chain of joints, need tens of passes to agree.
constexpr Real kImpactTolerance = 1e-9;
constexpr int kMostImpactPasses = 256;
// A pair pressed last step (its warm start) if that impulse changed how fast it closes by more than
// this share of the threshold: bodies resting under gravity press by g dt or more a step, where a
// touching rack in zero gravity presses by its rounding alone (1e-17 N s).
constexpr Real kPressedShare = 1e-3;

bool done(Real change, Real largest) { return change <= kImpactTolerance * largest; }

// The normal velocity of a point (eq. 4 and 11 along n) from its rows in lane l.
[[gnu::always_inline]] inline Real normal_velocity(const BodyState& sa, const BodyState& sb, const Vec3& normal, const PointLanes& p, int l) {
  return (sa.v - sb.v).dot(normal) + sa.w.dot(lane(p.ra_cross_n, l)) - sb.w.dot(lane(p.rb_cross_n, l));
}

// What this sub-step's warm start added to a point's normal velocity, from its rows in lane l, or
// at lever arms ra, rb.
[[gnu::always_inline]] inline Real warm_normal_velocity(const WarmStartChange& a, const WarmStartChange& b, const Vec3& normal, const PointLanes& p, int l) {
  return (a.dv - b.dv).dot(normal) + a.dw.dot(lane(p.ra_cross_n, l)) - b.dw.dot(lane(p.rb_cross_n, l));
}
Real warm_normal_velocity(const WarmStartChange& a, const WarmStartChange& b, const Vec3& normal, const Vec3& ra, const Vec3& rb) {
  return (a.dv + a.dw.cross(ra) - b.dv - b.dw.cross(rb)).dot(normal);
}

// `tangent` made perpendicular to `normal` again, turned as little as it can be.
Vec3 across(const Vec3& tangent, const Vec3& normal) { return (tangent - tangent.dot(normal) * normal).normalized(); }

}  // namespace

// A manifold in lane l of its block (one that can bounce is alone, in lane 0: contact_prepare.cpp).
bool ContactSolver::bounce_lane(int place, SolverBodies& solver_bodies, Real h) {
  const int index = lane_of_place_[place].block, l = lane_of_place_[place].lane;  // l is captured: no structured binding
  ManifoldLanes& block = lanes_[index];
  PointLanes* rows = &lane_points_[block.first_point];
  // A pair pressing nowhere in this sub-step may be landing: slower than the threshold, an impact
  // too, plastic. (So the points of a face that lands flat are answered together.) The lanes'
  // own data first: a pressed pair that cannot bounce, a resting stack's, is done.
  const bool unpressed = this->unpressed(block, l);
  if (!block.can_bounce && !unpressed) return false;
  BodyState& sa = solver_bodies.states[block.a[l]];
  BodyState& sb = solver_bodies.states[block.b[l]];
  // An approach is the bodies' own, with and without what this sub-step's warm start added (a
  // load carried on: last sub-step's impulses again, which the soft rows answer): the slower of the
  // two. Taken for an approach, a load's push would be returned with the restitution (a light box
  // pinched between two heavy balls, its contacts' impulses thrown back and forth between them,
  // gained energy sub-step after sub-step); without the push that holds a pair apart, a heap's
  // resting pairs would bounce on top of it and never settle. Still from the lanes: most pairs end
  // here, before their constraints are read.
  const WarmStartChange& warm_a = solver_bodies.warm[size_t(block.a[l])];
  const WarmStartChange& warm_b = solver_bodies.warm[size_t(block.b[l])];
  const Vec3 normal = lane(block.normal, l);
  const Real fast_enough = unpressed ? landing_speed_ : impact_threshold_;
  bool closing = false;
  for (int i = 0; i < block.points && !closing; ++i) {
    const Real vn = normal_velocity(sa, sb, normal, rows[i], l);
    closing = std::max(vn, vn - warm_normal_velocity(warm_a, warm_b, normal, rows[i], l)) < -fast_enough;
  }
  if (!closing) return false;
  ManifoldConstraint& m = manifolds_[place];
  ContactConstraint* points = &constraints_[m.first];
  bool pressed = false;
  for (int i = 0; i < m.count; ++i)
    pressed = pressed || points[i].normal_impulse > kPressedShare * impact_threshold_ * rows[i].normal_mass[l];
  // A pair bounces again in the same step (a later impact of a pack closing it again) only if it
  // did not press last step. One that did is held by a load (the rows of a tall pyramid, whose
  // soft contacts close at over 0.5 m/s as it settles): bounced over and over within a step it
  // pumps the stack up; once, as every pair may, it does not.
  if (m.bounce_speed > 0 && pressed) return false;
  const bool can_bounce = block.can_bounce && m.restitution > 0;
  if (!can_bounce && !unpressed) return false;
  const BodyInertia& ia = solver_bodies.inertia[m.a];
  const BodyInertia& ib = solver_bodies.inertia[m.b];

  // 1, 2. The hits, found at the geometry of the sub-step's start; then again at the moment the
  // first of them meets, where the impulses act.
  ContactAnchors anchors[kMaxManifoldPoints];
  anchors_in_lane(block, l, m, anchors);
  Real separation[kMaxManifoldPoints];
  bool apart = true;  // every point: a landing comes from apart
  for (int i = 0; i < m.count; ++i) {
    separation[i] = impact_separation(m, anchors[i], sa, sb);
    apart = apart && separation[i] > kTouching;
  }
  if (!can_bounce && !apart) return false;
  Hit hits[kMaxManifoldPoints];
  bool hit[kMaxManifoldPoints] = {};
  Real acceleration = 0;  // gravity's, of A relative to B along the normal
  // `meet_at_tau`: the points known to meet at `tau` (meets_at), if not found to meet before.
  auto find_hits = [&](const ImpactGeometry& g, const bool* meet_at_tau = nullptr, Real tau = 0) {
    acceleration = ((sa.inv_mass > 0 ? gravity_ : Vec3::Zero()) - (sb.inv_mass > 0 ? gravity_ : Vec3::Zero())).dot(g.normal);
    bool any_hit = false;
    for (int i = 0; i < m.count; ++i) {
      const Real vn_now = relative_velocity(sa, sb, g.ra[i], g.rb[i]).dot(g.normal);
      const Real vn = std::max(vn_now, vn_now - warm_normal_velocity(warm_a, warm_b, g.normal, g.ra[i], g.rb[i]));
      const bool bounces = can_bounce && vn < -impact_threshold_;
      const Real restitution = bounces ? m.restitution : 0, threshold = bounces ? impact_threshold_ : landing_speed_;
      hit[i] = (bounces || (unpressed && apart)) &&
               (meets(separation[i], vn, acceleration, restitution, threshold, h, hits[i]) ||
                (meet_at_tau && meet_at_tau[i] && meets_at(separation[i], vn, acceleration, restitution, threshold, h, tau, hits[i])));
      any_hit = any_hit || hit[i];
    }
    return any_hit;
  };
  // Closing fast but not meeting in this sub-step: the rows at its start, so that the soft
  // contact's speculative rows, which may close the gap and no more, see the pair as the bounce does.
  const ImpactGeometry now = impact_geometry(m, anchors, sa, ia, sb, ib, 0);
  if (!find_hits(now)) {
    write_impact_rows(place, now, nullptr, separation, solver_bodies, true);
    return false;
  }
  // A pair that pressed last step is in contact already: its moment of contact is now (a box
  // rocking onto its other edge, a settling stack), and its bodies' motion stays the solver's.
  Real first_meeting = pressed ? 0 : h;
  for (int i = 0; i < m.count; ++i)
    if (hit[i]) first_meeting = std::min(first_meeting, hits[i].tau);
  // Two spheres meet at that moment by its construction: the normal there turns to their line of
  // centres, which may change how fast they close, not whether. Found again along it, a hit near
  // the sub-step's end would otherwise fall past it and be left to the relax pass's inelastic rows.
  const bool spheres = m.radius_a > 0 && m.radius_b > 0;
  bool first[kMaxManifoldPoints] = {};
  for (int i = 0; i < m.count; ++i) first[i] = spheres && hit[i] && hits[i].tau == first_meeting;
  const ImpactGeometry g = impact_geometry(m, anchors, sa, ia, sb, ib, first_meeting);
  if (!find_hits(g, first, first_meeting)) return false;
  write_impact_rows(place, g, hit, separation, solver_bodies, true);

  // 3. The normal impulses, the points that meet together, Gauss-Seidel forwards and backwards so
  // that no point of a face that lands flat takes more than its share. The pair's other points take
  // part too, as the soft contact's speculative rows do (they may push, to close their gap in what
  // is left of the sub-step and no further): a box rocking onto its other edge is held at the edge
  // it rests on, or a hair above it, not driven in by the turn the landing gives it. One that
  // touches may not approach at all.
  bool holds[kMaxManifoldPoints] = {};
  Real hold_target[kMaxManifoldPoints] = {};
  const Real rest = h - first_meeting;
  for (int i = 0; i < m.count; ++i) {
    if (hit[i]) continue;
    const Real gap = separation[i] + first_meeting * normal_velocity(sa, sb, g.normal, rows[i], l);
    holds[i] = gap <= kTouching || rest > 0;
    hold_target[i] = gap <= kTouching ? 0 : -gap / rest;
  }
  JointSolver* joints = joints_ && (joints_->jointed(m.a) || joints_->jointed(m.b)) ? joints_ : nullptr;
  // Without joints bounces run on several threads at once: the pair's own two slots; with joints
  // (one thread) the cluster's too.
  const int pair[2] = {m.a, m.b};
  std::span<const int> moved(pair);
  if (joints) {
    impact_bodies_.assign({m.a, m.b});
    joints->begin_impact(m.a, m.b);
    for (int slot : joints->impact_slots())
      if (slot != m.a && slot != m.b) impact_bodies_.push_back(slot);
    moved = impact_bodies_;
  }
  // The bodies at the moment of contact: the impulses act there, the joints held there too.
  for (int slot : moved) advance(solver_bodies.states[slot], first_meeting);
  auto apply = [&](int i, Real impulse) {
    add_velocity(sa, sa.inv_mass * impulse * g.normal, impulse * lane(rows[i].angular_a, l));
    add_velocity(sb, -(sb.inv_mass * impulse * g.normal), -(impulse * lane(rows[i].angular_b, l)));
  };
  Real impulse[kMaxManifoldPoints] = {};
  for (int pass = 0; pass < kMostImpactPasses; ++pass) {
    Real change = 0, largest = 0;
    for (int k = 0; k < m.count; ++k) {
      const int i = pass % 2 ? m.count - 1 - k : k;
      if (!hit[i] && !holds[i]) continue;
      const Real vn = normal_velocity(sa, sb, g.normal, rows[i], l);
      const Real target = hit[i] ? hits[i].target : hold_target[i];
      const Real new_impulse = std::max(impulse[i] + rows[i].normal_mass[l] * (target - vn), Real(0));
      apply(i, new_impulse - impulse[i]);
      change = std::max(change, std::abs(new_impulse - impulse[i]));
      impulse[i] = new_impulse;
      largest = std::max(largest, new_impulse);
    }
    if (joints) change = std::max(change, joints->hold(solver_bodies, 1 / h));
    if (pass > 0 && done(change, largest)) break;
  }
  Real bounced = 0;
  for (int i = 0; i < m.count; ++i) {
    rows[i].total_normal_impulse[l] += impulse[i];
    if (!hit[i]) continue;
    bounced += impulse[i];
    m.hit_points |= uint8_t(1u << i);
    impact_shift_[m.first + i] = g.moved_a + g.ra[i] - anchors[i].anchor_a;
  }

  // 4. Friction: the manifold's rows at the points that meet, within mu times the bounce, solved
  // exactly (friction.h); again while the joints held change the sliding.
  if (block.friction[l] > 0 && bounced > 0) {
    Eigen::Matrix<Real, 2, 1> friction = Eigen::Matrix<Real, 2, 1>::Zero();
    for (int pass = 0; pass < kMostImpactPasses; ++pass) {
      const Eigen::Matrix<Real, 2, 1> before_pass = friction;
      impact_friction(block, l, bounced, friction, sa, sb);
      if (!joints) break;
      const Real change = std::max((friction - before_pass).cwiseAbs().maxCoeff(), joints->hold(solver_bodies, 1 / h));
      if (pass > 0 && done(change, bounced)) break;
    }
    block.total_tangent_impulse1[l] += friction[0];
    block.total_tangent_impulse2[l] += friction[1];
  }

  // The friction rows for the rest of the step, the soft contact's: at all the points' centroid.
  write_impact_rows(place, g, nullptr, separation, solver_bodies, false);

  // 5. Every body the impact moved moves on from the moment of contact with its new velocity: back
  // to the sub-step's start along it, where the positions' integration takes it from.
  for (int slot : moved) advance(solver_bodies.states[slot], -first_meeting);
  for (int i = 0; i < m.count; ++i)
    if (hit[i]) m.bounce_speed = std::max(m.bounce_speed, hits[i].u);
  return true;
}

// The rows of manifold `place` (in its lane) written again at the geometry `g`, friction's at the
// centroid of the points that meet (`hit`), or of them all (null: the soft contact's); the normal
// rows too, or friction's alone. Two spheres take their line of centres as the normal: the normal,
// tangents and friction impulses turn to it, and each point's separation stays what it is now.
void ContactSolver::write_impact_rows(int place, const ImpactGeometry& g, const bool* hit, const Real* separation,
                                      const SolverBodies& solver_bodies, bool normal_rows) {
  const auto [index, l] = lane_of_place_[place];
  ManifoldLanes& block = lanes_[index];
  ManifoldConstraint& m = manifolds_[place];
  PointLanes* rows = &lane_points_[block.first_point];
  const BodyState& sa = solver_bodies.states[m.a];
  const BodyState& sb = solver_bodies.states[m.b];
  if (g.normal != m.normal) {
    const Vec3 friction = block.tangent_impulse1[l] * m.tangent1 + block.tangent_impulse2[l] * m.tangent2;
    const Vec3 total = block.total_tangent_impulse1[l] * m.tangent1 + block.total_tangent_impulse2[l] * m.tangent2;
    m.tangent1 = across(m.tangent1, g.normal);
    m.tangent2 = g.normal.cross(m.tangent1);
    m.normal = g.normal;
    // Neither turns (spheres): the solver's separation is (dp_a - dp_b + anchor_a - anchor_b) . n + adjusted.
    for (int i = 0; i < m.count; ++i)
      rows[i].adjusted_separation[l] = separation[i] - (sa.dp - sb.dp + lane(rows[i].anchor_a, l) - lane(rows[i].anchor_b, l)).dot(m.normal);
    set_lane(block.normal, l, m.normal);
    set_lane(block.tangent1, l, m.tangent1);
    set_lane(block.tangent2, l, m.tangent2);
    block.tangent_impulse1[l] = friction.dot(m.tangent1);
    block.tangent_impulse2[l] = friction.dot(m.tangent2);
    block.total_tangent_impulse1[l] = total.dot(m.tangent1);
    block.total_tangent_impulse2[l] = total.dot(m.tangent2);
  }
  Vec3 centre_a = Vec3::Zero(), centre_b = Vec3::Zero();
  int counted = 0;
  for (int i = 0; i < m.count; ++i)
    if (!hit || hit[i]) centre_a += g.ra[i], centre_b += g.rb[i], ++counted;
  const RowGeometry rows_geometry{m.normal, m.tangent1, m.tangent2, m.count, g.ra, g.rb, centre_a / counted, centre_b / counted,
                                  sa.inv_mass, sb.inv_mass, &g.inv_inertia_a, &g.inv_inertia_b};
  if (normal_rows) set_rows(block, rows, l, rows_geometry);
  else set_friction_rows(block, l, rows_geometry);
}

void ContactSolver::anchors_in_lane(const ManifoldLanes& block, int l, const ManifoldConstraint& m, ContactAnchors* anchors) const {
  for (int i = 0; i < m.count; ++i) {
    const PointLanes& p = lane_points_[block.first_point + i];
    anchors[i] = {lane(p.anchor_a, l), lane(p.anchor_b, l), p.adjusted_separation[l], constraints_[m.first + i].feature};
  }
}

bool ContactSolver::bounce_manifolds(int place, int width, SolverBodies& solver_bodies, Real h) {
  bool bounced = false;
  for (int l = 0; l < width; ++l) bounced |= bounce_lane(place + l, solver_bodies, h);
  return bounced;
}

}  // namespace impulse::physics
