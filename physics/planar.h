// A planar lock: a body that moves only in a plane normal to a world axis and turns only about
// that axis, as on a blackboard (a Galton board, Newton's cradle, dominoes, billiards in two
// dimensions), with the same impulses as in three.
//
// The lock is a constraint with its own reaction, as Bullet's linear and angular factors and
// MuJoCo's planar joint are: the body's inverse mass and inertia are those of the constrained body,
// so every impulse the solver computes (eq. 13's effective mass included) is the one the
// constrained body takes.
// - Turning: the body turns about the axis e only, so an angular impulse L changes its spin by
//   e (e . L) / I_ee with I_ee = e . I_world e: the world inverse inertia is e e^T / I_ee
//   (planar_inverse_inertia). Every impulse's turn goes through that matrix, so the spin about
//   the plane's own axes stays exactly zero; the gyroscopic torque w x I w is perpendicular to
//   w = e w_e, so the lock's reaction takes all of it and the spin about e is kept.
// - Moving: the solver's inverse mass is one number for all directions, so the lock takes the
//   velocity along e away (hold_in_plane) before the contacts see it (after gravity) and before
//   the positions move; the body's coordinate along e then never changes, to the bit. An impulse
//   along a normal that lies in the plane (between bodies that are symmetric about one plane: a
//   sphere centred in it, a box with a face parallel to it) has nothing along e, so it is the
//   constrained body's exactly. One whose normal leaves the plane by n_e (a body beside the plane
//   touching one in it) is computed with the body free along e, and the lock takes its part along
//   e away: momentum in the plane is still exchanged equal and opposite, but the bounce along the
//   normal is short by about n_e^2 of the free one's.
#pragma once
#include "physics/math.h"

namespace impulse::physics {

// The world axis a locked body's plane is normal to: 0 x (the plane y-z), 1 y (x-z), 2 z (x-y).
inline constexpr int kNotPlanar = -1;

// The inverse inertia of a body that turns about the world axis `axis` only: e e^T / (e . I e).
inline Mat3 planar_inverse_inertia(const Mat3& inertia_world, int axis) {
  Mat3 inverse = Mat3::Zero();
  inverse(axis, axis) = 1 / inertia_world(axis, axis);
  return inverse;
}

// The velocities the lock allows: none along the axis, spin about it only. Exactly zero, so that
// the coordinate along the axis never moves.
inline void hold_in_plane(Vec3& v, Vec3& w, int axis) {
  if (axis == kNotPlanar) return;
  v[axis] = 0;
  const Real spin = w[axis];
  w.setZero();
  w[axis] = spin;
}

}  // namespace impulse::physics
