// The world: bodies, settings, and the fixed-step loop that moves them.
#pragma once
#include "physics/body.h"
#include "physics/body_state.h"
#include "physics/contact.h"
#include "physics/contact_finder.h"
#include "physics/island.h"
#include "physics/materials.h"
#include "physics/outside_response.h"
#include "physics/joint_solver.h"
#include "physics/contact_solver.h"
#include "physics/response_method.h"
#include "physics/rigid_body_view.h"
#include "physics/soft_step.h"
#include "physics/stack_sink.h"
#include "physics/step_record.h"
#include "physics/share_chooser.h"
#include "physics/thread_team.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace impulse::physics {

struct WorldSettings {
  Vec3 gravity{0, -9.81, 0};
  Real time_step = Real(1) / 60;   // s, fixed
  int substeps = 12;               // solver sub-steps per step at most (Box2D v3's soft step); 10 let
                                   // the contacts be stiff (120 Hz) enough that a 20-box stack sinks
                                   // < 1 cm, and still stable (contact_constraint.h); bodies moving
                                   // into each other too deep take all 12 (moving_overlap)
  int min_substeps = 4;            // at least, when no stack needs more:
  Real stack_sink = 0.007;         // m: as few sub-steps as keep every stack from sinking more than
                                   // this into its soft contacts (stack_sink.h); 0: always `substeps`
  Real moving_overlap = 0.0025;    // m: a contact of a moving body overlapping more than this, or a
                                   // twentieth of the thinner body's thinnest size, takes `substeps`
                                   // (stack_sink.h); 0: off
  Real linear_slop = 0.005;        // m; speculative contacts start 4 slops away
  ResponseMethod method = ResponseMethod::impulse;
  bool printed_eq8_sign = false;   // workshop method only: eq. 8/13's numerator as printed, -(1 - e),
                                   // the erratum, run to show what goes wrong (ERRATA.md)
  bool reference_listing = false;  // workshop method only: listing 1 corrected (listing_reference.h), the
                                   // answer a student's response is graded beside
  OutsideResponseMaker response;   // workshop method only: a student's AddCollisionImpulse in place of
                                   // listing 1's page (outside_response.h); empty: the page
  ContactSolverSettings contact;
  std::vector<PairMaterial> pair_materials;  // a scene's own friction and restitution for pairs of kinds (materials.h)
  PenaltySettings penalty;
  SleepSettings sleep;
  Real joint_hertz = 60;           // stiffness of the joints' position correction
  Real joint_damping_ratio = 2;
  int threads = 0;                 // threads that share the step's work; 0: one per core, each step shared
                                   // or not as has run faster lately (share_chooser.h). The contact search
                                   // uses them all; a sweep, at most two (the world's one cut,
                                   // sweep_schedule.h). The results are the same, bit for bit, for any count.
};

class World {
 public:
  explicit World(WorldSettings settings = {});

  // Adds a body and returns its index. Throws std::invalid_argument with the reason when the
  // definition is impossible (negative mass, zero radius, ...).
  int add_body(const BodyDef& def);

  // Advances one fixed time step. Throws std::runtime_error naming the body when a body's state
  // is no longer finite (NaN or infinity never reaches the caller's renderer).
  void step();
  // What the last step did: its contacts and impulses, energies and momenta. Gathered when first
  // asked for after a step (a renderer asks once a frame; a benchmark, like Bullet's step, never),
  // and valid until the next step.
  const StepRecord& record() const;

  // Joins two bodies (or a body and the world, kWorld) at their current poses; returns its index.
  // Throws std::invalid_argument for an impossible joint.
  int add_joint(const JointDef& def);
  const std::vector<Joint>& joints() const { return joints_; }

  const std::vector<Body>& bodies() const { return bodies_; }
  Body& body(int index) { return bodies_.at(index); }
  const WorldSettings& settings() const { return settings_; }
  // The friction and restitution of contacts between two bodies (materials.h; friction 0 when the
  // world's friction is off).
  ContactMaterial contact_material(int body_a, int body_b) const;
  Real time() const { return time_; }
  int substeps() const { return substeps_; }  // in the last step (between min_substeps and substeps)
  int64_t step_count() const { return step_count_; }

 private:
  // What a teaching method applied at a contact over the step, for the records: along the normal,
  // and on the tangents of tangent_basis(normal).
  struct TeachingImpulse {
    Real normal = 0, tangent1 = 0, tangent2 = 0;
  };

  void find_contacts(int threads);
  int choose_substeps();
  // The response, by method (response_method.cpp).
  void respond(Real dt, Real h);
  void solve_impulse(Real h);
  void solve_workshop(Real dt);
  void solve_projection(Real dt);
  void solve_penalty(Real h);
  void move_bodies(Real h);
  void solve_joints(Real h, bool use_bias);
  template <class Page>
  void for_each_plain_contact(Page&& page);
  TeachingImpulse respond_outside(const Contact& contact, RigidBody& a, RigidBody& b, Real penetration);
  void load_states();
  void integrate_velocities(Real h);
  void integrate_velocity(BodyState& s, const BodyInertia& inertia, Real h) const;
  static void integrate_position(BodyState& s, const BodyInertia& inertia, Real h);
  void integrate_positions(Real h);
  void store_states();
  void check_finite() const;
  void fill_record() const;

  WorldSettings settings_;
  int substeps_ = 1;
  int fewer_since_ = 0, most_needed_lately_ = 0;  // steps needing fewer sub-steps, and the most they needed
  StackSink stack_sink_;
  std::vector<Body> bodies_;
  SolverBodies solver_bodies_;  // by slot (ContactSolver::slots()), the world's still one last
  std::vector<Contact> contacts_;
  std::vector<uint8_t> awake_;
  ContactFinder contact_finder_;
  Islands islands_;
  std::vector<Joint> joints_;
  JointSolver joint_solver_;
  std::vector<std::pair<int, int>> links_;  // body pairs joined by joints, for the islands
  std::vector<int> anchored_;  // bodies jointed to the world: what holds their islands, for sleep
  ContactSolver contact_solver_;
  SoftStep soft_step_;
  std::unique_ptr<OutsideResponse> response_;  // settings_.response's, for this world alone
  std::vector<TeachingImpulse> teaching_impulses_;  // per contact, this step's, for the teaching methods' records
  std::unique_ptr<ThreadTeam> team_;  // on the heap: the solver keeps its address, and World can move
  ShareChooser share_chooser_{false};
  // The lowest index store_states() found not finite, or the body count. On the heap: World moves.
  std::unique_ptr<std::atomic<int>> non_finite_body_ = std::make_unique<std::atomic<int>>(0);
  mutable StepRecord record_;
  mutable int64_t recorded_step_ = -1;  // the step_count_ record_ was gathered at
  Real time_ = 0;
  int64_t step_count_ = 0;
};

}  // namespace impulse::physics
