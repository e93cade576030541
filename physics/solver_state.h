// What the solver works on during one step: a copy of each body's velocities and the motion
// since the step began. Kept apart from Body (as Box2D v3 keeps b2BodyState apart from b2Body).
#pragma once
#include "physics/math.h"

namespace impulse::physics {

struct alignas(64) BodyState {
  Vec3 v = Vec3::Zero();               // linear velocity
  Vec3 w = Vec3::Zero();               // angular velocity
  Vec3 dp = Vec3::Zero();              // displacement since the step began
  Quat dq = Quat::Identity();          // rotation since the step began
  Real inv_mass = 0;
  Mat3 inv_inertia = Mat3::Zero();     // world space, fixed for the step
  // For the gyroscopic term, only for bodies whose inertia is not the same about every axis.
  bool gyroscopic = false;
  Vec3 inertia_local = Vec3::Zero();   // principal moments (boxes: the local axes)
  Quat orientation0 = Quat::Identity();  // at step start
};

// Velocity of A's point at ra relative to B's point at rb: v + w x r for each (eq. 11, corrected).
inline Vec3 relative_velocity(const BodyState& sa, const BodyState& sb, const Vec3& ra, const Vec3& rb) {
  return (sa.v + sa.w.cross(ra)) - (sb.v + sb.w.cross(rb));
}

// Changes a moving body's velocities. A still body's (static or asleep) is not even written: the
// other thread may be reading it (the ground under both halves of a heap), and a write, even of
// the same value, takes its cache line away from that core.
inline void add_velocity(BodyState& s, const Vec3& dv, const Vec3& dw) {
  if (s.inv_mass == 0) return;
  s.v += dv;
  s.w += dw;
}

// +P on A at ra and -P on B at rb, linear and angular (eq. 14, corrected: the world-space inverse
// inertia tensor, and minus for B).
inline void apply_impulse(BodyState& sa, BodyState& sb, const Vec3& ra, const Vec3& rb, const Vec3& impulse) {
  add_velocity(sa, sa.inv_mass * impulse, sa.inv_inertia * ra.cross(impulse));
  add_velocity(sb, -(sb.inv_mass * impulse), -(sb.inv_inertia * rb.cross(impulse)));
}

// Inverse of the effective mass along direction d at anchors ra, rb:
// 1/m_a + 1/m_b + d . [(I_a^-1 (r_a x d)) x r_a + (I_b^-1 (r_b x d)) x r_b]  (eq. 13's denominator)
inline Real inverse_effective_mass(const BodyState& sa, const BodyState& sb, const Vec3& ra, const Vec3& rb, const Vec3& d) {
  const Vec3 ang_a = (sa.inv_inertia * ra.cross(d)).cross(ra);
  const Vec3 ang_b = (sb.inv_inertia * rb.cross(d)).cross(rb);
  return sa.inv_mass + sb.inv_mass + d.dot(ang_a + ang_b);
}

inline Real safe_inverse(Real k) { return k > 0 ? 1 / k : 0; }

// Soft constraint coefficients (Box2D v3's b2Softness, from Erin Catto's "Solver2D" notes):
// a spring of `hertz` with damping ratio `zeta`, solved implicitly over a sub-step of h seconds.
struct Softness {
  Real bias_rate = 0;
  Real mass_scale = 1;
  Real impulse_scale = 0;
};

inline Softness make_softness(Real hertz, Real zeta, Real h) {
  if (hertz == 0) return {0, 1, 0};
  const Real omega = 2 * kPi * hertz;
  const Real a1 = 2 * zeta + h * omega;
  const Real a2 = h * omega * a1;
  const Real a3 = 1 / (1 + a2);
  return {omega / a1, a2 * a3, a3};
}

}  // namespace impulse::physics
