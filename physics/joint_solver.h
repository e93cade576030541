// Solves joints by sequential impulses inside the soft step, like contacts (Box2D v3 joint.c):
// each joint's velocity error is removed, and its position error by a soft spring.
#pragma once
#include "physics/body.h"
#include "physics/joint.h"
#include "physics/body_state.h"
#include "physics/softness.h"

#include <vector>

namespace impulse::physics {

// A joint made from its definition at the bodies' current poses. Throws std::invalid_argument.
Joint make_joint(const JointDef& def, const std::vector<Body>& bodies);

class JointSolver {
 public:
  // The solver's bodies have one slot per body and, last, a still one standing for the world.
  // `slots`: where each body's state is (ContactSolver::slots()); the world's is after them all.
  void prepare(std::vector<Joint>& joints, const std::vector<Body>& bodies, const std::vector<int>& slots, Real hertz,
               Real damping_ratio, Real h);
  void warm_start(SolverBodies& bodies) const;
  void solve(SolverBodies& bodies, Real inv_h, bool use_bias);  // accumulates into the joints

  // Joints held through an impact (contact_bounce.cpp): whether a body's slot hangs on a joint;
  // then, for an impact between two slots, the joints linked to either through joints, each pass
  // of hold() solving their rows rigidly (no softness, no position bias) to zero relative velocity,
  // with impulses of the impact's own: the warm start's are left as they are. hold() returns the
  // largest change of an impulse in the pass (N s), for the caller to iterate until it is small.
  bool jointed(int slot) const { return slot < int(cluster_of_slot_.size()) && cluster_of_slot_[slot] >= 0; }
  void begin_impact(int slot_a, int slot_b);
  const std::vector<int>& impact_slots() const { return impact_slots_; }  // the bodies of those joints
  Real hold(SolverBodies& bodies, Real inv_h);

 private:
  struct Prepared {
    Joint* joint;
    int a, b;                  // indices into states (the world is the last)
    Vec3 anchor_a, anchor_b;   // world offsets from each centre, at step start
    Vec3 delta_centre;         // centre B - centre A, at step start
    Vec3 axis_a, axis_b;       // hinge axes in world space, at step start
    Real length = 0;
    int cluster = -1;          // the joints linked through shared bodies share one
  };
  // How a pass solves a joint's rows: with the soft step's softness, or rigidly (scale 1, no bias).
  struct Rows {
    Real bias_rate = 0, mass_scale = 1, impulse_scale = 0;
  };
  static Real solve_joint(const Prepared& p, SolverBodies& bodies, Real inv_h, const Rows& rows, JointImpulse& impulse);

  std::vector<Prepared> prepared_;
  Softness softness_;
  std::vector<int> cluster_of_slot_;  // -1: on no joint
  std::vector<int> impact_joints_;    // begin_impact()'s
  std::vector<int> impact_slots_;
  std::vector<JointImpulse> impact_impulses_;
};

}  // namespace impulse::physics
