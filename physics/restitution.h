// The moment of impact (eq. 5, v_n+ = -e v_n-, with eq. 8 and 13's 1 + e), its kernels on plain
// data: when a point meets within a sub-step and how fast, where each body's surface is at that
// moment (the lever arms r_a, r_b of eq. 13), and the bodies moved to that moment and back. ContactSolver's bounce stage (contact_bounce.cpp) runs them on a manifold
// and applies the impulses: the normal ones to e times the speed at which the surfaces meet, then
// the contact's own friction rows within mu times them (listing 1's order), with the joints held.
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
// bodies in space) kImpactFloor of it, so that the slow hits after a break obey eq. 5 too.
constexpr Real kImpactFloor = Real(0.02);
constexpr Real kThresholdGravity = Real(9.81);  // m/s^2, the default [world] gravity's
inline Real impact_threshold(Real restitution_threshold, const Vec3& gravity) {
  return restitution_threshold * std::max(kImpactFloor, gravity.norm() / kThresholdGravity);
}
// Slower hits are plastic, the soft contact's; a pair apart and pressing nowhere that closes at
// more than this share of the threshold is landing: an impact too, plastic (contact_bounce.cpp),
// so that the points of a face that lands flat are stopped together. Slower closings are a
// resting pile's settling.
constexpr Real kLandingShare = Real(0.1);

// How a point meets within a sub-step of h, timed exactly under the constant relative acceleration
// `a` along the normal (gravity's): the surfaces, `gap` apart at the start, meet after `tau` at
// `touch` and part at u = -e touch (eq. 5). Semi-implicit Euler's velocity lags its position by
// half a sub-step (its state (x, v) is the exact state (x, v + a h/2)), so the velocity to aim for
// at the end of the sub-step is u + a (h/2 - tau).
struct Hit {
  Real gap = 0;     // m apart at the sub-step's start (0 when they overlap)
  Real tau = 0;     // s into the sub-step when they meet
  Real touch = 0;   // m/s, the normal velocity at which they meet (< 0)
  Real u = 0;       // m/s, the parting speed
  Real target = 0;  // m/s, the normal velocity at the end of the sub-step
};

// Whether a point `separation` apart now, at normal velocity `vn` (this sub-step's gravity
// included), meets within the sub-step closing faster than `threshold`; if so, `hit` says how.
bool meets(Real separation, Real vn, Real a, Real restitution, Real threshold, Real h, Hit& hit);
// The same for a point known to meet at `tau` (the first of its pair to meet, at the geometry of
// that moment): how fast, if it closes faster than `threshold`.
bool meets_at(Real separation, Real vn, Real a, Real restitution, Real threshold, Real h, Real tau, Hit& hit);

// A pair at the moment its surfaces meet: the normal, and for each point the lever arms from each
// body's centre to the point where the surfaces meet (eq. 13's r_a and r_b, r_a - r_b = x_b - x_a:
// one world point, so that the impulses keep angular momentum), and each body's world inverse
// inertia then. Where the point lives (physics/README.md, "Where the contact point lives"):
// - a sphere's point is on its surface towards the other body, -R n from its centre, however it
//   spins; two spheres meet on the line of their centres at that moment, which is the normal;
// - else the point is carried by the body whose feature it is: a box's corner against a plane or
//   a still body, an incident corner against a reference face; a point that both make (crossing
//   edges, an incident edge cut by a side plane) lies midway between the two surfaces' points.
// A body's point turns with it from the start of the step (its anchor, contact_constraint.h).
struct ImpactGeometry {
  Vec3 normal = Vec3::UnitY();
  int count = 0;
  Vec3 ra[kMaxManifoldPoints], rb[kMaxManifoldPoints];
  Mat3 inv_inertia_a = Mat3::Zero(), inv_inertia_b = Mat3::Zero();
  Vec3 moved_a = Vec3::Zero();  // A's centre's displacement since the step began
};

// The geometry of manifold `m` (points[0..m.count)) `tau` into the sub-step whose start the
// states hold.
ImpactGeometry impact_geometry(const ManifoldConstraint& m, const ContactAnchors* points, const BodyState& sa, const BodyInertia& ia,
                               const BodyState& sb, const BodyInertia& ib, Real tau);

// A point's separation at the sub-step's start: separation_now(), the solver rows', but for two
// spheres, whose gap is measured on their line of centres as impact_geometry() takes the normal.
Real impact_separation(const ManifoldConstraint& m, const ContactAnchors& c, const BodyState& sa, const BodyState& sb);

// A body moved on by t along its velocity, turned by its angular velocity (back, for t < 0): to
// the moment of contact, where an impact's impulses act; and back from it along the new velocity.
// So a bounced pair moves as the exact motion does, meeting at the moment of contact and parting
// from there, and angular momentum about any point is kept (every impulse acts at the bodies'
// positions then).
void advance(BodyState& s, Real t);

}  // namespace impulse::physics
