// How deep stacks sink into their soft contacts, to choose the sub-step count.
//
// A soft contact of stiffness k = m (2 pi hertz)^2 gives way by F / k under a load F, and the
// giving adds up from the ground along every chain of bodies resting on one another: a 20-box
// stack at 120 Hz sinks 6.6 mm (measured: 6.6). Contacts can be at most a fifth of the sub-step
// rate stiff (kMaxHertzPerSubstepRate, contact_constraint.h), so a stack that must sink less needs more sub-steps, and a heap
// of low piles needs fewer.
#pragma once
#include "physics/body.h"
#include "physics/contact_solver.h"

#include <vector>

namespace impulse::physics {

class StackSink {
 public:
  // The deepest a body sinks times w^2: (F / m) per contact added along the chains of supports,
  // a body on several the mean of theirs weighted by their loads, from the loads of the solver's
  // last step (sub-steps of h seconds). `up` is against gravity.
  Real deepest_give(const ContactSolver& solver, const std::vector<Body>& bodies, const Vec3& up, Real h);

 private:
  struct Support {  // between two moving bodies
    int upper, lower;
    Real give;       // load force over the contact's mass
    Real load;       // its impulse
  };
  std::vector<Support> supports_;
  std::vector<Real> give_below_;  // per body; kept for bodies asleep
  std::vector<Real> weighted_, weight_;  // per body: its supports' gives times their loads, and the loads
  // Scratch for the topological order, per body: supports under it not yet counted; where its
  // supports of bodies above start in above_ (the supports, grouped by lower body).
  std::vector<int> unsupported_below_, first_above_, next_above_, above_, ready_;
};

// Whether a contact of a moving body (its fastest point above `speed`, as sleep measures it)
// overlaps more than `overlap` or a twentieth of the thinner body's thinnest size. A body squeezed
// while it moves (a domino bouncing off the ground under the one that fell on it) sinks into soft
// contacts further than its load alone presses it, and comes back out at their slow rate
// (softness.h): stiffer contacts, more sub-steps, keep it within what a frame shows.
bool moving_overlap_too_deep(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, Real overlap, Real speed);

}  // namespace impulse::physics
