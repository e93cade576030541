#include "physics/penalty_method.h"

#include "physics/normal_impulse.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impulse::physics {

PenaltyImpulse apply_penalty_impulse(RigidBody& a, RigidBody& b, const Vec3& point, const Vec3& normal, Real penetration,
                                     Real friction, const PenaltySettings& settings, Real h) {
  PenaltyImpulse applied;
  if (penetration <= 0) return applied;
  const Vec3 ra = point - a.centre, rb = point - b.centre;
  // k = m w^2 and c = 2 zeta m w, with m the pair's effective mass along the normal (eq. 13's).
  const Real omega = 2 * std::numbers::pi * settings.hertz;
  const Vec3 ra_cross_n = ra.cross(normal), rb_cross_n = rb.cross(normal);
  const Real mass = safe_inverse(inverse_effective_mass_of_rows(a.inv_mass + b.inv_mass, ra_cross_n, a.world_inv_inertia * ra_cross_n,
                                                                rb_cross_n, b.world_inv_inertia * rb_cross_n));
  const Vec3 dv = relative_velocity(a, b, ra, rb);
  // F = k x - c v along the normal, pushing only.
  const Real force = std::max(mass * omega * omega * penetration - 2 * settings.damping_ratio * mass * omega * dv.dot(normal), Real(0));
  const Real jn = force * h;
  add_impulse(a, b, ra, rb, jn * normal);
  applied.normal = jn;

  // Friction: the impulse that would stop the sliding this sub-step, at most mu * jn.
  if (friction == 0) return applied;
  Vec3 t1, t2;
  tangent_basis(normal, t1, t2);
  const Vec3 dvt = relative_velocity(a, b, ra, rb);
  Real j1 = -safe_inverse(inverse_effective_mass(a.inv_mass, a.world_inv_inertia, b.inv_mass, b.world_inv_inertia, ra, rb, t1)) * dvt.dot(t1);
  Real j2 = -safe_inverse(inverse_effective_mass(a.inv_mass, a.world_inv_inertia, b.inv_mass, b.world_inv_inertia, ra, rb, t2)) * dvt.dot(t2);
  // Within the Coulomb disc |j| <= mu jn, measured with hypot: not friction.h's clamp, which
  // rounds differently, and the catalogue's penalty videos are pinned to these bits.
  const Real length = std::hypot(j1, j2), limit = friction * jn;
  if (length > limit) {
    j1 *= limit / length;
    j2 *= limit / length;
  }
  add_impulse(a, b, ra, rb, j1 * t1 + j2 * t2);
  applied.tangent1 = j1;
  applied.tangent2 = j2;
  return applied;
}

}  // namespace impulse::physics
