// Soft constraints (Box2D v3's b2Softness, from Erin Catto's "Solver2D" notes): a constraint's
// position error is corrected as by a spring of `hertz` with damping ratio `zeta`, solved
// implicitly over a sub-step of h seconds. Contacts and joints alike.
#pragma once
#include "physics/math.h"

namespace impulse::physics {

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

// A soft row's compliance over its own K_ii: (1 - keep) / mass = impulse_scale / (mass_scale / K_ii)
// (normal_impulse.h's soft_normal_row); 0 for a rigid one.
inline Real soft_share(const Softness& s) { return s.impulse_scale / s.mass_scale; }

}  // namespace impulse::physics
