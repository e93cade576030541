// The workshop's three simpler collision responses, kept for teaching next to the default
// solver (contact_solver.h). Each works on contact constraints prepared by ContactSolver::prepare
// and adds what it applied to their step totals, so every method draws and plots the same way.
#pragma once
#include "physics/contact_solver.h"
#include "physics/response_method.h"

#include <vector>

namespace impulse::physics {

// Listing 1 (AddCollisionImpulse), once per touching contact: the normal impulse of eq. 13 with
// (1+e), plus the listing's "hack fix" jn += 1.5 * penetration, then an unclamped tangent impulse
// along the sliding direction (skipped when there is none: normalising a zero vector is NaN).
// `printed_sign` runs the erratum instead, -(1 - e) as eq. 8 and 13 are printed: for teaching only.
void apply_workshop_impulses(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states,
                             bool friction, bool printed_sign = false);

// Section 1's projection method: each touching pair is moved apart along the normal by its
// penetration, shared by inverse mass. Velocities are left as they are.
void project_apart(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states);

// Section 1's penalty method, for one sub-step of h: a spring-damper force along the normal
// while the bodies overlap (pushing only), and Coulomb friction up to mu times that force.
void apply_penalty_forces(std::vector<ContactConstraint>& constraints, std::vector<BodyState>& states,
                          const PenaltySettings& settings, Real h);

}  // namespace impulse::physics
