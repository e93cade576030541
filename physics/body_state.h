// What the solver works on during one step, per body slot, in two arrays (Box2D v3 and Box3D keep
// b2BodyState apart from b2BodySim the same way):
// - BodyState, hot: what every sweep reads and writes (the velocities, and the motion since the
//   step began that the sub-steps integrate). Small, so that a sweep pulls in few cache lines.
// - BodyInertia, cold: fixed for the step, read where a constraint is built, by the bounces, the
//   joints and the gyroscopic term (the sweeps use rows prepared from it).
#pragma once
#include "physics/math.h"
#include "physics/planar.h"

#include <vector>

namespace impulse::physics {

struct BodyState {
  Vec3 v = Vec3::Zero();       // linear velocity
  Vec3 w = Vec3::Zero();       // angular velocity
  Vec3 dp = Vec3::Zero();      // displacement since the step began
  Real inv_mass = 0;           // 0: does not move this step (static, asleep, or the world's slot)
  Quat dq = Quat::Identity();  // rotation since the step began
};
// Box3D's b3BodyState is 56 bytes of floats; this is the same in doubles. A sweep reads two of
// these per manifold: keep it small.
static_assert(sizeof(BodyState) == 112, "BodyState is the sweeps' hot data: keep it at 112 bytes");

struct BodyInertia {
  Mat3 inv_inertia = Mat3::Zero();        // world space (eq. 14's I^-1), fixed for the step; 0 when still
  // For the gyroscopic term, only for bodies whose inertia is not the same about every axis.
  Quat orientation0 = Quat::Identity();   // at step start
  Vec3 inertia_local = Vec3::Zero();      // principal moments (boxes: the local axes)
  bool gyroscopic = false;
  int planar_axis = kNotPlanar;           // the body's planar lock (planar.h)
};

// A body's velocities changed by the contacts' warm start of the sub-step (contact_warm_start.cpp):
// last sub-step's impulses applied again, a load carried on, not an approach (contact_bounce.cpp).
struct WarmStartChange {
  Vec3 dv = Vec3::Zero();
  Vec3 dw = Vec3::Zero();
};

// The solver's bodies by slot (ContactSolver::slots()), the last one a still one for the world.
struct SolverBodies {
  std::vector<BodyState> states;
  std::vector<BodyInertia> inertia;
  std::vector<WarmStartChange> warm;  // this sub-step's, zeroed with the velocities' integration
};

// Changes a moving body's velocities. A still body's (static or asleep) is not even written: the
// other thread may be reading it (the ground under both halves of a heap), and a write, even of
// the same value, takes its cache line away from that core.
inline void add_velocity(BodyState& s, const Vec3& dv, const Vec3& dw) {
  if (s.inv_mass == 0) return;
  s.v += dv;
  s.w += dw;
}

// +P on A at ra and -P on B at rb, linear and angular (eq. 9 and 14, corrected: the world-space
// inverse inertia tensor, and minus for B).
inline void apply_impulse(BodyState& sa, const Mat3& inv_inertia_a, BodyState& sb, const Mat3& inv_inertia_b, const Vec3& ra,
                          const Vec3& rb, const Vec3& impulse) {
  add_velocity(sa, sa.inv_mass * impulse, inv_inertia_a * ra.cross(impulse));
  add_velocity(sb, -(sb.inv_mass * impulse), -(inv_inertia_b * rb.cross(impulse)));
}

// dq' = 1/2 (0, w) dq, one explicit step, renormalised: exactly a turn about w by 2 atan(h |w| / 2),
// the Cayley transform cay(h [w]x) of the rotation. The positions' step, and where a bounce finds a
// turning body at the moment of contact.
inline void turn(Quat& dq, const Vec3& w, Real h) {
  const Quat spin(0, w.x() * h / 2, w.y() * h / 2, w.z() * h / 2);
  dq.coeffs() += (spin * dq).coeffs();
  dq.normalize();
}

// Velocity of A's point at ra relative to B's point at rb: v + w x r for each (eq. 11, corrected),
// then v_ab = v_a - v_b (eq. 4).
inline Vec3 relative_velocity(const BodyState& sa, const BodyState& sb, const Vec3& ra, const Vec3& rb) {
  return (sa.v + sa.w.cross(ra)) - (sb.v + sb.w.cross(rb));
}

}  // namespace impulse::physics
