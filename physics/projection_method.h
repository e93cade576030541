// Section 1's projection method, as one page: a touching pair is moved apart along the normal by
// its penetration, shared by inverse mass. Velocities are left as they are, so the bodies meet
// again next step (what the section says goes wrong with it).
#pragma once
#include "physics/rigid_body_view.h"

namespace impulse::physics {

void project_apart(RigidBody& a, RigidBody& b, const Vec3& normal, Real penetration);

}  // namespace impulse::physics
