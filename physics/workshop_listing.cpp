#include "physics/workshop_listing.h"

#include "physics/normal_impulse.h"

namespace impulse::physics {

ListingImpulse add_collision_impulse(RigidBody& c0, RigidBody& c1, const Vec3& hit_point, const Vec3& normal, Real penetration,
                                     const ListingOptions& options) {
  ListingImpulse applied;
  // Both objects are non movable (line 50).
  if (c0.inv_mass + c1.inv_mass == 0) return applied;
  const Vec3 r0 = hit_point - c0.centre;
  const Vec3 r1 = hit_point - c1.centre;

  // Relative velocity; moving apart faster than 1 cm/s needs no impulse (lines 55-66).
  const Vec3 dv = relative_velocity(c0, c1, r0, r1);
  if (-dv.dot(normal) < -0.01) return applied;

  // NORMAL impulse: eq. 13 with (1 + e) (or the printed 1 - e), n.n kept as printed, then the
  // listing's bias "proportional to penetration": a length added to an impulse.
  const Real e = options.restitution;
  const Real factor = options.printed_sign ? 1 - e : 1 + e;
  const Real norm_div =
      inverse_effective_mass(c0.inv_mass, c0.world_inv_inertia, c1.inv_mass, c1.world_inv_inertia, r0, r1, normal, normal.dot(normal));
  Real jn = -factor * dv.dot(normal) / norm_div;
  jn = jn + penetration * 1.5;  // the "hack fix" (line 85)
  add_impulse(c0, c1, r0, r1, jn * normal);
  applied.normal = jn;

  // TANGENT impulse, from the same dv, not clamped by friction (line 119 says so).
  if (!options.tangential) return applied;
  Vec3 tangent = dv - dv.dot(normal) * normal;
  if (tangent.norm() < 1e-9) return applied;  // the guard the listing lacks
  tangent.normalize();
  const Real tang_div = inverse_effective_mass(c0.inv_mass, c0.world_inv_inertia, c1.inv_mass, c1.world_inv_inertia, r0, r1, tangent);
  const Real jt = -dv.dot(tangent) / tang_div;
  add_impulse(c0, c1, r0, r1, jt * tangent);
  applied.tangent = jt;
  applied.tangent_direction = tangent;
  return applied;
}

}  // namespace impulse::physics
