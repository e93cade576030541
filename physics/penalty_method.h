// Section 1's penalty method, as one page: while two bodies overlap, a spring-damper force along
// the normal pushes them apart, and Coulomb friction resists their sliding up to mu times it.
// Applied as the impulse of that force over one sub-step of h.
#pragma once
#include "physics/response_method.h"
#include "physics/rigid_body_view.h"

namespace impulse::physics {

// What it applied, for the records: along the normal, and on the tangents of tangent_basis(normal).
struct PenaltyImpulse {
  Real normal = 0, tangent1 = 0, tangent2 = 0;
};

// `friction`: the pair's mu (0: none).
PenaltyImpulse apply_penalty_impulse(RigidBody& a, RigidBody& b, const Vec3& point, const Vec3& normal, Real penetration,
                                     Real friction, const PenaltySettings& settings, Real h);

}  // namespace impulse::physics
