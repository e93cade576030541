// Listing 1 corrected as ERRATA.md says: the answer to the workshop's exercise, and the engine's
// reference for a student's own AddCollisionImpulse (outside_response.h). It is the text of
// assets/workshop/listing1_corrected.cpp in the engine's doubles, called as listing 1's page is
// (once per touching contact per step, workshop_listing.h), so that a correct student's file and
// this page move the bodies alike, and `impulse grade` holds both to the same laws.
//
// What it corrects in the listing: the pair's e instead of 0 (line 71), and none below
// kListingBounceSpeed (a resting body would jiggle); Baumgarte's position correction instead of
// the "hack fix" jn += 1.5 penetration (line 85), which adds a length to an impulse and so holds
// up light bodies and lets heavy ones sink; jn >= 0 (a contact pushes); friction clamped to
// Coulomb's |jt| <= mu jn (line 119's comment). The listing's signs are kept: they are right.
#pragma once
#include "physics/rigid_body_view.h"
#include "physics/workshop_listing.h"

namespace impulse::physics {

inline constexpr Real kListingBounceSpeed = 0.5;   // m/s: slower approaches do not bounce
inline constexpr Real kListingBias = 0.5;          // Baumgarte's beta: this share of the depth closed per step
inline constexpr Real kListingSlop = 0.005;        // m of depth left alone, so that touching bodies stay touching

struct ReferenceListingOptions {
  Real restitution = 0;  // e, the pair's
  Real friction = 0;     // mu, the pair's (0 with friction off)
  Real time_step = Real(1) / 60;
};

ListingImpulse reference_collision_impulse(RigidBody& c0, RigidBody& c1, const Vec3& hit_point, const Vec3& normal, Real penetration,
                                           const ReferenceListingOptions& options);

}  // namespace impulse::physics
