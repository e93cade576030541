#include "physics/teaching_methods.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impulse::physics {

void apply_workshop_impulses(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states,
                             bool friction, bool printed_sign) {
  for (ContactConstraint& c : constraints) {
    BodyState& s0 = states[c.a];
    BodyState& s1 = states[c.b];
    const Real penetration = -current_separation(c, s0, s1);
    if (penetration < 0) continue;  // the listing only sees intersecting pairs
    if (s0.inv_mass + s1.inv_mass == 0) continue;  // both objects are non movable
    const Vec3& r0 = c.anchor_a;
    const Vec3& r1 = c.anchor_b;
    const Vec3& normal = c.normal;

    // Relative velocity; moving apart faster than 1 cm/s needs no impulse (listing lines 59-66).
    const Vec3 dv = relative_velocity(s0, s1, r0, r1);
    if (-dv.dot(normal) < -0.01) continue;

    // NORMAL impulse, eq. 13 with (1+e) (or the printed 1-e), then the listing's bias "proportional
    // to penetration".
    const Real e = c.restitution;
    const Real factor = printed_sign ? 1 - e : 1 + e;
    const Real norm_div = normal.dot(normal) * (s0.inv_mass + s1.inv_mass) +
                          normal.dot((s0.inv_inertia * r0.cross(normal)).cross(r0) + (s1.inv_inertia * r1.cross(normal)).cross(r1));
    Real jn = -factor * dv.dot(normal) / norm_div;
    jn = jn + penetration * 1.5;  // the "hack fix" (line 85): a length added to an impulse
    apply_impulse(s0, s1, r0, r1, jn * normal);
    c.total_normal_impulse += jn;

    // TANGENT impulse, from the same dv, not clamped by friction (line 119 says so).
    if (!friction) continue;
    Vec3 tangent = dv - dv.dot(normal) * normal;
    if (tangent.norm() < 1e-9) continue;  // the guard the listing lacks
    tangent.normalize();
    const Real tang_div = s0.inv_mass + s1.inv_mass +
                          tangent.dot((s0.inv_inertia * r0.cross(tangent)).cross(r0) + (s1.inv_inertia * r1.cross(tangent)).cross(r1));
    const Real jt = -dv.dot(tangent) / tang_div;
    apply_impulse(s0, s1, r0, r1, jt * tangent);
    c.total_tangent_impulse1 += jt * tangent.dot(c.tangent1);
    c.total_tangent_impulse2 += jt * tangent.dot(c.tangent2);
  }
}

void project_apart(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states) {
  for (ContactConstraint& c : constraints) {
    BodyState& sa = states[c.a];
    BodyState& sb = states[c.b];
    const Real total = sa.inv_mass + sb.inv_mass;
    const Real penetration = -current_separation(c, sa, sb);
    if (penetration <= 0 || total == 0) continue;
    sa.dp += c.normal * (penetration * sa.inv_mass / total);
    sb.dp -= c.normal * (penetration * sb.inv_mass / total);
  }
}

void apply_penalty_forces(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states,
                          const PenaltySettings& settings, Real h) {
  const Real omega = 2 * std::numbers::pi * settings.hertz;
  for (ContactConstraint& c : constraints) {
    BodyState& sa = states[c.a];
    BodyState& sb = states[c.b];
    const Real penetration = -current_separation(c, sa, sb);
    if (penetration <= 0) continue;
    const Real mass = c.normal_mass;
    const Vec3 dv = relative_velocity(sa, sb, c.anchor_a, c.anchor_b);
    // F = k x - c v along the normal, pushing only.
    const Real force = std::max(mass * omega * omega * penetration - 2 * settings.damping_ratio * mass * omega * dv.dot(c.normal), Real(0));
    const Real jn = force * h;
    apply_impulse(sa, sb, c.anchor_a, c.anchor_b, jn * c.normal);
    c.total_normal_impulse += jn;

    // Friction: the impulse that would stop the sliding this sub-step, at most mu * jn.
    if (c.friction == 0) continue;
    const Vec3 dvt = relative_velocity(sa, sb, c.anchor_a, c.anchor_b);
    Real j1 = -safe_inverse(inverse_effective_mass(sa, sb, c.anchor_a, c.anchor_b, c.tangent1)) * dvt.dot(c.tangent1);
    Real j2 = -safe_inverse(inverse_effective_mass(sa, sb, c.anchor_a, c.anchor_b, c.tangent2)) * dvt.dot(c.tangent2);
    const Real length = std::hypot(j1, j2), limit = c.friction * jn;
    if (length > limit) {
      j1 *= limit / length;
      j2 *= limit / length;
    }
    apply_impulse(sa, sb, c.anchor_a, c.anchor_b, j1 * c.tangent1 + j2 * c.tangent2);
    c.total_tangent_impulse1 += j1;
    c.total_tangent_impulse2 += j2;
  }
}

}  // namespace impulse::physics
