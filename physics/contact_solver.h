// The default method's contacts, solved by sequential impulses: per point, accumulated normal
// impulses clamped to push only (eq. 13 as corrected, normal_impulse.h) with a soft position
// correction; per manifold (all the points between one pair of bodies), Coulomb friction on two
// tangents and a twist at the points' centroid (friction.h), and restitution answered at the
// moment the surfaces meet (restitution.h).
//
// Each step: plan() orders the manifolds for the sweeps (sweep_schedule.h), prepare() builds
// their constraints (contact_constraint.h), warm started from the last step, and packs them two
// side by side for the sweeps (contact_lanes.h); the sub-steps' stages (soft_step.h) then run the
// sweeps below; store_impulses() keeps the impulses for the records and the next warm start. The
// stages, a file each (Box3D's b3PrepareContacts ... b3StoreImpulses):
//   contact_prepare.cpp     plan(), prepare(): constraints, rows, warm start, lanes
//   contact_warm_start.cpp  warm_start_manifolds()
//   contact_solve.cpp       solve_manifolds(): the biased solve, and the relax solve (no bias)
//   contact_bounce.cpp      the bounces, in the biased solve and the impact passes
//   contact_store.cpp       add_to_totals(), store_impulses()
//
// Where the impulses are: during the sub-steps, in the packed lanes (the sweeps and the bounces
// add to them); after store_impulses(), copied back into the constraints and the warm-start
// lists. Manifolds are named by their place in the sweeps' order.
#pragma once
#include "physics/body.h"
#include "physics/body_state.h"
#include "physics/contact.h"
#include "physics/contact_constraint.h"
#include "physics/contact_lanes.h"
#include "physics/materials.h"
#include "physics/restitution.h"
#include "physics/softness.h"
#include "physics/sweep_schedule.h"
#include "physics/thread_team.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

class JointSolver;

class ContactSolver {
 public:
  // Plans this step's sweeps over the contacts' manifolds and how `threads` of `team` share them
  // (1: the caller alone); slots() then
  // says where each body's state goes (the solver's indices, in states and in the constraints).
  // `pair_materials` (materials.h) must outlive the step.
  void plan(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, const std::vector<PairMaterial>& pair_materials,
            ThreadTeam& team, int threads);
  const std::vector<int>& slots() const { return schedule_.slots(); }
  const std::vector<int>& body_of_slot() const { return schedule_.bodies(); }
  // Builds the constraints of the planned contacts, warm started from the last step's impulses
  // (contact_prepare.cpp). The last slot must be a still one (the world's): a block's empty lane
  // reads it.
  void prepare(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, const SolverBodies& solver_bodies,
               const ContactSolverSettings& settings, const Vec3& gravity, Real h);

  // The joints held through the bounces of this step's sub-steps (null: none). With joints, the
  // world plans the contacts for one thread: a bounce then solves joints beyond its two bodies.
  void hold_joints(JointSolver* joints) { joints_ = joints; }

  // The sweeps' work on the manifold at `place`, or on it and the next side by side (width 2),
  // for the stages of a sub-step (soft_step.h), in the sweeps' order.
  void warm_start_manifolds(int place, SolverBodies& solver_bodies) const;
  // Returns whether one bounced (restitution; only with use_bias).
  bool solve_manifolds(int place, int width, SolverBodies& solver_bodies, Real inv_h, bool use_bias);
  // The bounces alone, for the impact passes after the biased solve (soft_step.h): whether one bounced.
  bool bounce_manifolds(int place, int width, SolverBodies& solver_bodies, Real h);
  void add_to_totals(int place);  // the sub-step's impulses to the step's totals, after the relax pass
  void end_substep() {
    backwards_ = !backwards_;  // the next sub-step goes through the points the other way
    ++substeps_;
  }

  // Keeps the impulses for warm starting the next step, shares each manifold's friction among its
  // points for the records, and notes each manifold's load.
  void store_impulses();
  const std::vector<ManifoldLoad>& loads() const { return loads_; }

  // In the sweeps' order, not the contacts' (constraint_of() maps one to the other).
  const std::vector<ContactConstraint>& constraints() const { return constraints_; }
  const std::vector<ManifoldConstraint>& manifolds() const { return manifolds_; }
  const ContactConstraint& constraint_of(int contact) const { return constraints_[constraint_of_contact_[contact]]; }
  // Its manifold: the normal and tangents of its impulses (a bounce's normal, for one that bounced).
  const ManifoldConstraint& manifold_of(int contact) const { return manifolds_[manifold_of_constraint(constraint_of_contact_[contact])]; }
  // Where the contact's impulses acted this step, relative to the point the narrow phase found at
  // its start: where the surfaces met, for a point that bounced; else nothing.
  Vec3 impact_shift(int contact) const {
    const int i = constraint_of_contact_[contact];
    const ManifoldConstraint& m = manifolds_[manifold_of_constraint(i)];
    return m.hit_points >> (i - m.first) & 1 ? impact_shift_[i] : Vec3::Zero();
  }
  // f(contact) for every contact, in the sweeps' order (after plan()).
  template <class F>
  void for_each_contact_in_sweep_order(F&& f) const {
    for (int manifold : schedule_.order())
      for (int i = groups_[manifold].first; i < groups_[manifold].second; ++i) f(i);
  }

  SweepSchedule& schedule() { return schedule_; }
  ThreadTeam& team() { return *team_; }
  // f(slot) for every body's slot, each on the thread whose sweeps move it (its data stays in that core).
  template <class F>
  void for_each_slot(F&& f) { schedule_.for_each_slot(*team_, f); }

 private:
  struct ManifoldWarm;
  void find_previous_pairs();
  void prepare_manifold(int place, const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                        const SolverBodies& solver_bodies, Real warm_scale);
  void prepare_shared_rows(ManifoldConstraint& m, const ContactAnchors* anchors, ManifoldLanes& block, int lane, const Body& body_a,
                           const Body& body_b, const SolverBodies& solver_bodies);
  static void warm_start_friction(ManifoldConstraint& m, const ManifoldWarm& previous);
  bool bounce_lane(int place, SolverBodies& solver_bodies, Real h);
  // Whether lane l of `block` pressed nowhere in this sub-step so far (it may be landing).
  bool unpressed(const ManifoldLanes& block, int l) const {
    for (int i = 0; i < block.points; ++i)
      if (lane_points_[block.first_point + i].normal_impulse[l] != 0) return false;
    return true;
  }
  void write_impact_rows(int place, const ImpactGeometry& g, const bool* hit, const Real* separation, const SolverBodies& solver_bodies,
                         bool normal_rows);
  int manifold_of_constraint(int constraint) const;
  ManifoldLanes& begin_lanes(int place, const ManifoldConstraint& m);
  void fill_lanes(int place, const ManifoldConstraint& m, const ContactAnchors* anchors);
  // Lane l's anchors of the block's points, as prepare() put them there.
  void anchors_in_lane(const ManifoldLanes& block, int l, const ManifoldConstraint& m, ContactAnchors* anchors) const;
  void copy_back(int place);
  template <int N, bool UseBias>
  IMPULSE_LANES_KERNEL void solve_lanes(ManifoldLanes& block, Mask2 solved, SolverBodies& solver_bodies, Real inv_h);

  std::vector<ContactConstraint> constraints_;
  std::vector<ManifoldConstraint> manifolds_;
  // The sweeps' data, two manifolds side by side, in the sweeps' order; and where each place's is.
  std::vector<ManifoldLanes> lanes_;
  std::vector<PointLanes> lane_points_;
  struct LanePlace { int block, lane; };
  std::vector<LanePlace> lane_of_place_;
  int world_slot_ = 0;  // a still state, for a block's empty lane
  std::vector<ManifoldLoad> loads_;  // per manifold, at the last store_impulses()
  std::vector<std::pair<int, int>> groups_;  // each manifold's contacts [first, end), in the contacts' order
  std::vector<int> constraint_of_contact_;
  std::vector<int> first_of_place_;  // each manifold's first constraint, counted before the threads build them
  // The warm start: each manifold's pair and place in the sweeps, in the contacts' order (by pair);
  // last step's constraints, manifolds and pairs; and where each manifold's pair is among those.
  struct PairPlace { uint64_t key; int manifold; };
  std::vector<PairPlace> pairs_;
  // What the warm start needs of a step, small and apart from the constraints (the lookups then
  // read a line or two): per point, its feature and impulse; per manifold, its points and friction.
  // Last step's, which prepare() reads; store_impulses() writes this step's over them.
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
  std::vector<PointWarm> warm_points_;
  std::vector<ManifoldWarm> warm_manifolds_;
  std::vector<PairPlace> previous_pairs_;
  std::vector<std::pair<int, int>> previous_range_;
  bool impulses_stored_ = false;  // store_impulses() since the last prepare()
  Real h_ = 0, stored_h_ = 0;      // this step's sub-step, and the stored impulses'
  int substeps_ = 0;               // this step's, so far
  ContactSolverSettings settings_;
  Real impact_threshold_ = 0;  // m/s: slower hits do not bounce (restitution.h, impact_threshold)
  Real landing_speed_ = 0;     // m/s: a pair apart and pressing nowhere that closes faster lands (contact_bounce.cpp)
  Vec3 gravity_ = Vec3::Zero();
  JointSolver* joints_ = nullptr;     // hold_joints()
  std::vector<Vec3> impact_shift_;    // per constraint, for the points that bounced (impact_shift())
  std::vector<int> impact_bodies_;    // a bounce's: the slots it moves
  Softness softness_;  // every contact's, for this step's sub-steps (prepare())
  bool backwards_ = false;  // this sub-step's order of a manifold's points (solve_lanes)
  ThreadTeam* team_ = nullptr;
  const std::vector<PairMaterial>* pair_materials_ = nullptr;  // the world's (plan())
  SweepSchedule schedule_;
};

}  // namespace impulse::physics
