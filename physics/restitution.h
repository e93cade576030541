// Restitution (eq. 5, v_n+ = -e v_n-, and eq. 8's 1 + e), answered where the surfaces meet: in the
// sub-step in which a pair closes faster than the restitution threshold, its points are bounced
// together to e times the speed at which they meet, predicted exactly under constant
// acceleration, and the pair is moved back by the time it spent parting too early. One pair at a
// time, in the contacts' order: so a hit passes along a row of touching bodies as in Newton's
// cradle, instead of being shared out inelastically first. Slower hits (resting contact) are left
// to the sweeps.
#pragma once
#include "physics/body_state.h"
#include "physics/contact_constraint.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

// How fast a pair must close to bounce. The threshold is for bodies that gravity holds together:
// a box or a ball resting on the floor, or boxes leaning in a heap, close a little every sub-step
// and rock at a few cm/s while they settle, and bouncing that would keep them jiggling. Those
// speeds come from gravity, so the threshold is in proportion to it: `restitution_threshold` at
// 9.81 m/s² (the default gravity), a sixth of it on the Moon, and in zero gravity (a rack of balls,
// bodies in space) kImpactFloor of it, so that the slow hits after a break obey eq. 5 too. (In
// proportion to |n . g| instead, a heap's leaning boxes bounced off each other for a minute.)
constexpr Real kImpactFloor = Real(0.02);
constexpr Real kThresholdGravity = Real(9.81);  // m/s^2, the default [world] gravity's
inline Real impact_threshold(Real restitution_threshold, const Vec3& gravity) {
  return restitution_threshold * std::max(kImpactFloor, gravity.norm() / kThresholdGravity);
}

// What a bounce applied, for the step's totals: the normal impulse at each point that hit, and
// friction's on the manifold's tangents.
struct BounceImpulses {
  bool hit[kMaxManifoldPoints] = {};
  Real normal[kMaxManifoldPoints] = {};
  bool friction = false;
  Real tangent1 = 0, tangent2 = 0;
};

// Bounces manifold `m` (its points `points[0..m.count)`) if it meets fast enough within this
// sub-step of h; returns whether it did. It reads the constraints' geometry (fixed for the step)
// and the bodies' states, changes the states, and returns what it applied for the caller to add
// to the step's totals (in the lanes, where the sub-steps keep them). Then m.bounce_shift says
// what to take back after the positions (take_back_bounce_shift).
bool bounce(ManifoldConstraint& m, const ContactConstraint* points, BodyState& sa, const BodyInertia& ia, BodyState& sb,
            const BodyInertia& ib, Real restitution_threshold, Real h, BounceImpulses& applied);

// The shift is taken back as a time shift of the pair: each body moves along its own velocity for
// the same dt. That changes neither momentum nor angular momentum (sum of v dt x m v = 0).
void take_back_bounce_shift(ManifoldConstraint& m, BodyState& sa, BodyState& sb);

}  // namespace impulse::physics
