// What the solver works on during one step: a copy of each body's velocities and the motion
// since the step began. Kept apart from Body (as Box2D v3 keeps b2BodyState apart from b2Body).
#pragma once
#include "physics/math.h"

namespace impulse::physics {

struct BodyState {
  Vec3 v = Vec3::Zero();               // linear velocity
  Vec3 w = Vec3::Zero();               // angular velocity
  Vec3 dp = Vec3::Zero();              // displacement since the step began
  Quat dq = Quat::Identity();          // rotation since the step began
  Real inv_mass = 0;
  Mat3 inv_inertia = Mat3::Zero();     // world space, fixed for the step
};

// Soft constraint coefficients (Box2D v3's b2Softness, from Erin Catto's "Solver2D" notes):
// a spring of `hertz` with damping ratio `zeta`, solved implicitly over a sub-step of h seconds.
struct Softness {
  Real bias_rate = 0;
  Real mass_scale = 1;
  Real impulse_scale = 0;
};

inline Softness make_softness(Real hertz, Real zeta, Real h) {
  if (hertz == 0) return {0, 1, 0};
  const Real omega = 2 * Real(3.14159265358979323846) * hertz;
  const Real a1 = 2 * zeta + h * omega;
  const Real a2 = h * omega * a1;
  const Real a3 = 1 / (1 + a2);
  return {omega / a1, a2 * a3, a3};
}

}  // namespace impulse::physics
