// Sequential impulses on contacts: accumulated, clamped normal impulses (eq. 13 as corrected),
// Coulomb friction on two tangents, soft position correction, and restitution as each contact is met.
#pragma once
#include "physics/body.h"
#include "physics/contact.h"
#include "physics/solver_state.h"

#include <vector>

namespace impulse::physics {

struct ContactSolverSettings {
  Real contact_hertz = 30;             // stiffness of the position correction
  Real contact_damping_ratio = 10;
  Real max_push_velocity = 3;          // m/s, fastest the correction moves bodies apart
  Real restitution_threshold = 0.5;    // m/s, slower hits do not bounce (no resting jiggle)
  bool friction = true;                // tangential impulses on or off (exercise 1)
};

// Rules for combining two bodies' materials (Box2D's): the larger restitution, and the geometric
// mean of the friction coefficients.
Real mix_restitution(Real a, Real b);
Real mix_friction(Real a, Real b);

struct ContactConstraint {
  int a = -1, b = -1;
  Vec3 normal, tangent1, tangent2;
  Vec3 anchor_a, anchor_b;             // contact point relative to each centre, at step start
  Real adjusted_separation = 0;        // separation - dot(anchor_a - anchor_b, normal)
  Real normal_mass = 0, tangent_mass1 = 0, tangent_mass2 = 0;
  Real friction = 0, restitution = 0;
  Softness softness;
  // Impulses of the current sub-step (warm started from the previous one).
  Real normal_impulse = 0, tangent_impulse1 = 0, tangent_impulse2 = 0;
  // Sums over the whole step, for the records.
  Real total_normal_impulse = 0, total_tangent_impulse1 = 0, total_tangent_impulse2 = 0;
  Real max_normal_impulse = 0;
  Real normal_acceleration = 0;        // of A relative to B along the normal, from gravity
  bool bounced = false;                // restitution applied this step
  Real bounce_shift = 0;               // m, separation to take back after this sub-step's positions
};

// Separation now, from how far each body has moved and turned since the step began.
inline Real current_separation(const ContactConstraint& c, const BodyState& sa, const BodyState& sb) {
  const Vec3 moved = (sa.dp - sb.dp) + (sa.dq * c.anchor_a - sb.dq * c.anchor_b);
  return moved.dot(c.normal) + c.adjusted_separation;
}

class ContactSolver {
 public:
  // Builds one constraint per contact. `warm` holds each contact's impulses from the last step
  // (three per contact, or empty for a new contact).
  void prepare(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
               const std::vector<BodyState>& states, const ContactSolverSettings& settings,
               const Vec3& gravity, Real h);
  void warm_start(std::vector<BodyState>& states) const;
  void solve(std::vector<BodyState>& states, Real inv_h, bool use_bias);
  void apply_bounce_shifts(std::vector<BodyState>& states);  // after integrating positions
  void end_substep();  // adds this sub-step's impulses to the step totals

  std::vector<ContactConstraint>& constraints() { return constraints_; }
  const std::vector<ContactConstraint>& constraints() const { return constraints_; }

 private:
  std::vector<ContactConstraint> constraints_;
  bool bounce(ContactConstraint& c, BodyState& sa, BodyState& sb, Real vn, Real separation, Real h);

  ContactSolverSettings settings_;
};

}  // namespace impulse::physics
