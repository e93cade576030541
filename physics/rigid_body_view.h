// A body as the workshop's teaching pages see it: listing 1's RigidBody (lines 3-23), the fields
// its AddCollisionImpulse reads and writes, as plain data. The world copies each body of a contact
// in, calls the page, and copies the velocities and displacement back into the solver's state.
#pragma once
#include "physics/math.h"

namespace impulse::physics {

struct RigidBody {
  Vec3 centre = Vec3::Zero();             // m_centre, where the step began
  Real inv_mass = 0;                      // m_invMass; 0: does not move (static or asleep)
  Mat3 world_inv_inertia = Mat3::Zero();  // m_worldInvInertia
  Vec3 lin_velocity = Vec3::Zero();       // m_linVelocity
  Vec3 ang_velocity = Vec3::Zero();       // m_angVelocity
  Vec3 displacement = Vec3::Zero();       // how far the centre has moved since the step began
};

// An impulse P applied at `hit_point`: +P on c0 and -P on c1, linear and angular (eq. 9 and 14,
// corrected: the world-space inverse inertia, and minus for c1; listing lines 88-95). A body
// that does not move is not written.
inline void add_impulse(RigidBody& c0, RigidBody& c1, const Vec3& r0, const Vec3& r1, const Vec3& impulse) {
  auto add = [](RigidBody& c, const Vec3& dv, const Vec3& dw) {
    if (c.inv_mass == 0) return;
    c.lin_velocity += dv;
    c.ang_velocity += dw;
  };
  add(c0, c0.inv_mass * impulse, c0.world_inv_inertia * r0.cross(impulse));
  add(c1, -(c1.inv_mass * impulse), -(c1.world_inv_inertia * r1.cross(impulse)));
}

// Velocity of c0's point at r0 relative to c1's point at r1 (eq. 11, corrected, and eq. 4;
// listing lines 55-59).
inline Vec3 relative_velocity(const RigidBody& c0, const RigidBody& c1, const Vec3& r0, const Vec3& r1) {
  return (c0.lin_velocity + c0.ang_velocity.cross(r0)) - (c1.lin_velocity + c1.ang_velocity.cross(r1));
}

}  // namespace impulse::physics
