// A scene file's `rotation`: degrees about x, then y, then z, each about the world axis,
// right-handed. Computed in arithmetic alone, without libm's sin and cos: glibc chooses their code
// by the CPU (an FMA version where there is FMA), and their last bits differ between the two, so a
// scene would start from other bits on another machine. These give the same bits on every x86-64
// machine (physics/README.md, "The same bits on every machine").
#pragma once
#include "physics/math.h"

#include <utility>

namespace impulse::demos {

// {sin, cos} of an angle in degrees: exact at multiples of 90, elsewhere within 1e-15.
std::pair<physics::Real, physics::Real> sin_cos_degrees(physics::Real degrees);

// The orientation that turns a body by degrees.x() about world x, then degrees.y() about world y,
// then degrees.z() about world z.
physics::Quat rotation_from_degrees(const physics::Vec3& degrees);

}  // namespace impulse::demos
