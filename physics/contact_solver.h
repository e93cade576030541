// Sequential impulses on contacts (the default method): per point, accumulated normal impulses
// clamped to push only (eq. 13 as corrected) with a soft position correction; per manifold (all
// the points between one pair of bodies), Coulomb friction on two tangents and a twist at the
// points' centroid, and restitution answered in the sub-step in which the surfaces meet.
//
// The constraints below are built per point and per manifold, and kept for the records, the
// bounces, the warm start and the teaching methods; the sweeps work on a packed copy, two
// manifolds side by side (ManifoldLanes, contact_lanes.cpp).
#pragma once
#include "physics/body.h"
#include "physics/contact.h"
#include "physics/lanes.h"
#include "physics/solver_state.h"
#include "physics/sweep_schedule.h"
#include "physics/thread_team.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace impulse::physics {

struct ContactSolverSettings {
  Real contact_hertz = 120;            // stiffness of the position correction, at most 1/6 of the
                                       // sub-step rate (see kMaxHertzPerSubstepRate)
  Real contact_damping_ratio = 10;
  Real max_push_velocity = 3;          // m/s, fastest the correction moves bodies apart
  Real restitution_threshold = 0.5;    // m/s, slower hits do not bounce (no resting jiggle)
  bool friction = true;                // tangential impulses on or off (exercise 1)
  Real rolling_resistance = 0;         // c: a sphere's contact resists rolling with a torque up to
                                       // c R N (R its radius, N the normal force); 0: a rigid ball
                                       // on a rigid plane rolls on for ever
};

// Contacts stiffer than this fraction of the sub-step rate are not stable. Box2D's rule is 1/4; at
// 1/4 (and 1/5) a wall of boxes one box thick (the pyramids of ../shared/bench/SCENES.md, even
// one of 21 boxes) starts to sway out of its plane, growing over seconds, whatever the damping
// ratio, passes or solve order; friction feeds it (without friction it stays still). At 1/6 and
// below every pyramid measured stood still.
constexpr Real kMaxHertzPerSubstepRate = Real(1) / 6;

// Rules for combining two bodies' materials (Box2D's): the larger restitution, and the geometric
// mean of the friction coefficients.
Real mix_restitution(Real a, Real b);
Real mix_friction(Real a, Real b);

// One contact point.
struct alignas(64) ContactConstraint {  // a cache line of its own at each end: threads build neighbours
  int a = -1, b = -1;
  uint32_t feature = 0;                // the contact's, to find it again next step
  Vec3 normal, tangent1, tangent2;
  Vec3 anchor_a, anchor_b;             // contact point relative to each centre, at step start
  Real adjusted_separation = 0;        // separation - dot(anchor_a - anchor_b, normal)
  Real normal_mass = 0;
  // The normal row's angular parts, fixed for the step: r x n, and I^-1 (r x n) for each body.
  Vec3 ra_cross_n = Vec3::Zero(), rb_cross_n = Vec3::Zero();
  Vec3 angular_a = Vec3::Zero(), angular_b = Vec3::Zero();
  Real friction = 0, restitution = 0;
  Real normal_impulse = 0;             // this sub-step's, warm started from the last one
  // Sums over the whole step, for the records.
  Real total_normal_impulse = 0, total_tangent_impulse1 = 0, total_tangent_impulse2 = 0;
  Real normal_acceleration = 0;        // of A relative to B along the normal, from gravity
};

// Separation now, from how far each body has moved and turned since the step began.
inline Real current_separation(const ContactConstraint& c, const BodyState& sa, const BodyState& sb) {
  const Vec3 moved = (sa.dp - sb.dp) + (rotate(sa.dq, c.anchor_a) - rotate(sb.dq, c.anchor_b));
  return moved.dot(c.normal) + c.adjusted_separation;
}

// The points between one pair of bodies, and their shared friction: what the records, the bounces
// and the warm start read. The rows the sweeps solve are built straight into its lane
// (ManifoldLanes).
struct alignas(64) ManifoldConstraint {
  int a = -1, b = -1;
  int first = 0, count = 0;            // its points in the constraint list
  bool bounced = false;                // restitution applied this step
  // Its points', which share them (one pair, one normal).
  Vec3 normal = Vec3::Zero(), tangent1 = Vec3::Zero(), tangent2 = Vec3::Zero();
  Real friction = 0, restitution = 0;
  Real tangent_impulse1 = 0, tangent_impulse2 = 0, twist_impulse = 0;  // this sub-step's
  Real total_tangent_impulse1 = 0, total_tangent_impulse2 = 0;
  Real bounce_shift = 0;               // m, separation to take back after this sub-step's positions
  Real bounce_speed = 0;               // m/s, the speed the pair parts at after its hit
};

// What the sweeps read and write, for two manifolds side by side (lanes.h): each field holds the
// first manifold's value in lane 0 and the second's in lane 1. A manifold solved alone leaves lane
// 1 empty (the still world's slot, no mass, no friction). Written by prepare() from the manifolds
// and their points, and copied back to them by store_impulses().
struct PointLanes {
  V3 anchor_a, anchor_b, ra_cross_n, rb_cross_n, angular_a, angular_b;
  Real2 adjusted_separation, normal_mass;
  Real2 normal_impulse, total_normal_impulse;
};

struct alignas(64) ManifoldLanes {
  int a[2], b[2];                  // slots
  int points = 0;                  // each manifold's
  int first_point = 0;             // in lane_points_
  bool can_bounce = false;         // either has restitution
  V3 normal, tangent1, tangent2;
  Real2 friction;
  Real2 turns_a, turns_b;          // 1 where the body's turning moves the points along the normal
  Real2 coupling[4][4];            // d(normal velocity at i) / d(impulse at j), for the points
  Real2 tangent_mass1, tangent_mass2, twist_mass;
  Real2 twist_radius;              // mean distance of the points from their centroid
  Real2 rolling_radius;            // rolling resistance times the spheres' radius, else 0
  // The friction rows' angular parts, fixed for the step: r x t at the points' centroid, and how
  // an impulse along t1, t2 or a twist about n turns each body (I^-1 (r x t), I^-1 n).
  V3 ra_cross_t1, ra_cross_t2, rb_cross_t1, rb_cross_t2;
  V3 turn_a1, turn_a2, turn_b1, turn_b2, twist_a, twist_b;
  Real2 tangent_impulse1, tangent_impulse2, twist_impulse;
  Real2 total_tangent_impulse1, total_tangent_impulse2;
};

// A manifold's load at the end of a step, for StackSink: its last sub-step's impulse and the sum of
// its points' normal masses. Small and apart from the constraints, so that the thread that
// reads it does not pull in the lines of the constraints that another thread solves.
struct ManifoldLoad {
  int a = -1, b = -1;  // slots
  Real impulse = 0, normal_mass = 0;
  Vec3 normal = Vec3::UnitY();
};

class ContactSolver {
 public:
  // Plans this step's sweeps over the contacts' manifolds and how `team` shares them; slots() then
  // says where each body's state goes (the solver's indices, in states and in the constraints).
  void plan(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, ThreadTeam& team);
  const std::vector<int>& slots() const { return schedule_.slots(); }
  const std::vector<int>& body_of_slot() const { return schedule_.bodies(); }
  // Builds the constraints of the planned contacts, warm started from the last step's impulses.
  // The last of `states` must be a still one (the world's): a block's empty lane reads it.
  void prepare(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
               const std::vector<BodyState>& states, const ContactSolverSettings& settings,
               const Vec3& gravity, Real h);
  void warm_start(std::vector<BodyState>& states);
  void solve(std::vector<BodyState>& states, Real inv_h, bool use_bias);
  void apply_bounce_shifts(std::vector<BodyState>& states);  // after integrating positions
  void end_substep();     // adds this sub-step's impulses to the step totals; the next goes the other way
  // f(slot) for every body's slot, each on the thread whose sweeps move it (its data stays in that core).
  template <class F>
  void for_each_slot(F&& f) { schedule_.for_each_slot(*team_, f); }

  // One whole sub-step for a world without joints: the calls above in the same order, with
  // integrate_velocity(slot) before and integrate_position(slot) halfway, all in one job of the
  // team (its threads meet at a barrier between the phases instead of being woken for each).
  template <class IntegrateVelocity, class IntegratePosition>
  void substep(std::vector<BodyState>& states, Real h, IntegrateVelocity&& integrate_velocity,
               IntegratePosition&& integrate_position);
  // Keeps them for warm starting the next step, shares each manifold's friction among its points
  // for the records, and notes each manifold's load.
  void store_impulses();
  const std::vector<ManifoldLoad>& loads() const { return loads_; }

  // In the sweeps' order, not the contacts' (constraint_of() maps one to the other).
  std::vector<ContactConstraint>& constraints() { return constraints_; }
  const std::vector<ContactConstraint>& constraints() const { return constraints_; }
  const std::vector<ManifoldConstraint>& manifolds() const { return manifolds_; }
  const ContactConstraint& constraint_of(int contact) const { return constraints_[constraint_of_contact_[contact]]; }

 private:
  void find_previous_pairs();
  ManifoldLanes& begin_lanes(int step, const ManifoldConstraint& m);
  void prepare_manifold(ManifoldConstraint& m, ManifoldLanes& block, int lane, const Body& body_a, const Body& body_b,
                        const std::vector<BodyState>& states) const;
  struct ManifoldWarm;
  static void warm_start_friction(ManifoldConstraint& m, const ManifoldWarm& previous);
  // The sweeps' work on manifold `index`, or on it and the next side by side (width 2; lanes.h).
  void warm_start_manifolds(int index, int width, std::vector<BodyState>& states) const;
  // Returns whether any bounced (restitution, only with use_bias).
  bool solve_manifolds(int index, int width, std::vector<BodyState>& states, Real inv_h, bool use_bias);
  void fill_lanes(int step, const ManifoldConstraint& m);
  void warm_start_lanes(const ManifoldLanes& block, std::vector<BodyState>& states) const;
  template <int N, bool Backwards, bool UseBias>
  void solve_lanes(ManifoldLanes& block, Mask2 solved, std::vector<BodyState>& states, Real inv_h);
  void copy_back(int step);
  void resist_rolling(const ManifoldLanes& block, Mask2 solved, Real2 normal_sum, BodyState* const sa[2], BodyState* const sb[2],
                      V3& wa, V3& wb) const;
  void shift_bounce(int index, std::vector<BodyState>& states);
  void add_to_totals(int index);
  bool bounce(int step, BodyState& sa, BodyState& sb, Real h);

  std::vector<ContactConstraint> constraints_;
  std::vector<ManifoldConstraint> manifolds_;
  // The sweeps' data, two manifolds side by side, in the sweeps' order; and where each step's is.
  std::vector<ManifoldLanes> lanes_;
  std::vector<PointLanes> lane_points_;
  struct LanePlace { int block, lane; };
  std::vector<LanePlace> lane_of_step_;
  int world_slot_ = 0;  // a still state, for a block's empty lane
  std::vector<ManifoldLoad> loads_;  // per manifold, at the last store_impulses()
  std::vector<std::pair<int, int>> groups_;  // each manifold's contacts [first, end), in the contacts' order
  std::vector<int> constraint_of_contact_;
  std::vector<int> first_of_step_;  // each manifold's first constraint, counted before the threads build them
  // The warm start: each manifold's pair and place in the sweeps, in the contacts' order (by pair);
  // last step's constraints, manifolds and pairs; and where each manifold's pair is among those.
  struct PairPlace { uint64_t key; int manifold; };
  std::vector<PairPlace> pairs_;
  // What the warm start needs of a step, small and apart from the constraints (the lookups then
  // read a line or two): per point, its feature and impulse; per manifold, its points and friction.
  // This step's (written by store_impulses()) and last step's.
  struct PointWarm {
    uint32_t feature = 0;
    Real normal_impulse = 0;
  };
  struct ManifoldWarm {
    int first = 0, count = 0;
    // Friction as a world vector: the tangents are rebuilt from each step's normal, and the basis
    // (tangent_basis) turns over where the normal's z changes sign.
    Vec3 friction_impulse = Vec3::Zero();
    Real twist_impulse = 0;
  };
  std::vector<PointWarm> warm_points_, previous_warm_points_;
  std::vector<ManifoldWarm> warm_manifolds_, previous_warm_manifolds_;
  std::vector<PairPlace> previous_pairs_;
  std::vector<std::pair<int, int>> previous_range_;
  bool impulses_stored_ = false;  // store_impulses() since the last prepare()
  Real h_ = 0, stored_h_ = 0;      // this step's sub-step, and the stored impulses'
  ContactSolverSettings settings_;
  Softness softness_;  // every contact's, for this step's sub-steps (prepare())
  bool backwards_ = false;  // this sub-step's order of a manifold's points (solve_lanes)
  ThreadTeam* team_ = nullptr;
  SweepSchedule schedule_;
  // Per thread that sweeps (two at most): the last sub-step epoch in which one of its manifolds
  // bounced. On the heap, as the sweeps' progress counters: atomics cannot move with the solver.
  struct alignas(64) BounceEpoch { std::atomic<uint64_t> value{0}; };
  std::unique_ptr<BounceEpoch[]> bounced_ = std::make_unique<BounceEpoch[]>(2);
};

template <class IntegrateVelocity, class IntegratePosition>
void ContactSolver::substep(std::vector<BodyState>& states, Real h, IntegrateVelocity&& integrate_velocity,
                            IntegratePosition&& integrate_position) {
  const uint64_t epoch = schedule_.new_epochs(4);
  const bool parallel = schedule_.parallel();
  auto meet = [&] { if (parallel) team_->barrier(); };
  schedule_.run(*team_, [&](int thread) {
    schedule_.slot_share(thread, integrate_velocity);
    meet();
    schedule_.sweep_share(thread, epoch, [&](int index, int width) { warm_start_manifolds(index, width, states); });
    meet();
    bool bounced = false;
    schedule_.sweep_share(thread, epoch + 1, [&](int index, int width) { bounced |= solve_manifolds(index, width, states, 1 / h, true); });
    if (bounced) bounced_[thread].value.store(epoch, std::memory_order_relaxed);  // only threads 0 and 1 have manifolds
    meet();
    schedule_.slot_share(thread, integrate_position);
    meet();
    // Most sub-steps nothing bounces (resting piles): then no sweep to take shifts back. The
    // barriers order the flags; every thread reads the same and takes the same way.
    if (bounced_[0].value.load(std::memory_order_relaxed) == epoch || bounced_[1].value.load(std::memory_order_relaxed) == epoch) {
      schedule_.sweep_share(thread, epoch + 2, [&](int index, int width) {
        for (int k = 0; k < width; ++k) shift_bounce(index + k, states);
      });
      meet();
    }
    schedule_.sweep_share(thread, epoch + 3, [&](int index, int width) {
      solve_manifolds(index, width, states, 1 / h, false);
      add_to_totals(index);  // the relax pass is the sub-step's last word on them
    });
  });
  backwards_ = !backwards_;
}

}  // namespace impulse::physics
