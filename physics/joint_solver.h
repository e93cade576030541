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

 private:
  struct Prepared {
    Joint* joint;
    int a, b;                  // indices into states (the world is the last)
    Vec3 anchor_a, anchor_b;   // world offsets from each centre, at step start
    Vec3 delta_centre;         // centre B - centre A, at step start
    Vec3 axis_a, axis_b;       // hinge axes in world space, at step start
    Real length = 0;
  };
  std::vector<Prepared> prepared_;
  Softness softness_;
};

}  // namespace impulse::physics
