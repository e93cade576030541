#include "physics/listing_reference.h"

#include "physics/normal_impulse.h"

#include <algorithm>

namespace impulse::physics {

// Line for line as listing1_corrected.cpp: its comments say why.
ListingImpulse reference_collision_impulse(RigidBody& c0, RigidBody& c1, const Vec3& hit_point, const Vec3& normal, Real penetration,
                                           const ReferenceListingOptions& options) {
  ListingImpulse applied;
  if (c0.inv_mass + c1.inv_mass == 0) return applied;
  const Vec3 r0 = hit_point - c0.centre;
  const Vec3 r1 = hit_point - c1.centre;
  const Vec3 dv = relative_velocity(c0, c1, r0, r1);
  const Real relative_movement = -dv.dot(normal);
  if (relative_movement < -0.01) return applied;

  // NORMAL: eq. 13 with 1 + e, e only for an approach faster than kListingBounceSpeed, and the
  // depth beyond the slop closed by kListingBias of it per step, through the same denominator.
  const Real e = relative_movement < kListingBounceSpeed ? 0 : options.restitution;
  const Real norm_div =
      inverse_effective_mass(c0.inv_mass, c0.world_inv_inertia, c1.inv_mass, c1.world_inv_inertia, r0, r1, normal, normal.dot(normal));
  Real jn = -(1 + e) * dv.dot(normal) / norm_div;
  const Real depth = penetration - kListingSlop;
  if (depth > 0) jn += kListingBias / options.time_step * depth / norm_div;
  jn = std::max(jn, Real(0));
  add_impulse(c0, c1, r0, r1, jn * normal);
  applied.normal = jn;

  // TANGENT: along the sliding before the normal impulse (as the listing), |jt| <= mu jn.
  Vec3 tangent = dv - dv.dot(normal) * normal;
  if (tangent.norm() == 0) return applied;  // Normalize() of zero is zero: no tangent impulse
  tangent.normalize();
  const Real tang_div = inverse_effective_mass(c0.inv_mass, c0.world_inv_inertia, c1.inv_mass, c1.world_inv_inertia, r0, r1, tangent);
  const Real jt = std::clamp(-dv.dot(tangent) / tang_div, -options.friction * jn, options.friction * jn);
  add_impulse(c0, c1, r0, r1, jt * tangent);
  applied.tangent = jt;
  applied.tangent_direction = tangent;
  return applied;
}

}  // namespace impulse::physics
