// Listing 1 of the workshop, AddCollisionImpulse, as one page: the response a student writes.
// It sees one contact (two bodies, the hit point, the normal, the penetration) and changes the
// two bodies' velocities; the world calls it once per touching contact per step (the `workshop`
// method, response_method.h). A student's own AddCollisionImpulse fits the same seam.
#pragma once
#include "physics/rigid_body_view.h"

namespace impulse::physics {

struct ListingOptions {
  Real restitution = 0;       // e: the listing hard-codes 0 (line 71); here the pair's, mixed
  bool tangential = true;     // the tangent impulse (exercise 1 turns it off)
  bool printed_sign = false;  // eq. 8 and 13's numerator as printed, -(1 - e): the erratum, for teaching
};

// What the listing applied, for the records: J along the normal, and jt along `tangent`.
struct ListingImpulse {
  Real normal = 0;
  Real tangent = 0;
  Vec3 tangent_direction = Vec3::Zero();  // zero when no tangent impulse was applied
};

// The normal impulse of eq. 13 with (1 + e), plus the listing's "hack fix" J += 1.5 * penetration
// (line 85), then an unclamped tangent impulse along the sliding direction (line 119 says it is
// not clamped; skipped when there is no sliding: normalising a zero vector is NaN).
ListingImpulse add_collision_impulse(RigidBody& c0, RigidBody& c1, const Vec3& hit_point, const Vec3& normal, Real penetration,
                                     const ListingOptions& options);

}  // namespace impulse::physics
