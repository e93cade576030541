#include "physics/stack_sink.h"

#include <algorithm>

namespace impulse::physics {

Real StackSink::deepest_give(const ContactSolver& solver, const std::vector<Body>& bodies, const Vec3& up, Real h) {
  const auto& constraints = solver.constraints();
  const auto& body_of_slot = solver.body_of_slot();
  supports_.clear();
  for (const ManifoldConstraint& m : solver.manifolds()) {
    Real force = 0, mass = 0;
    for (int i = 0; i < m.count; ++i) {
      force += constraints[m.first + i].normal_impulse / h;
      mass += constraints[m.first + i].normal_mass;
    }
    if (force <= 0 || mass <= 0) continue;
    const bool a_above = constraints[m.first].normal.dot(up) > 0;  // the normal points from B to A
    const int upper = body_of_slot[a_above ? m.a : m.b], lower = body_of_slot[a_above ? m.b : m.a];
    if (bodies[lower].is_static()) {
      // Twice as stiff as between two moving bodies (staticSoftness): a quarter the give.
      supports_.push_back({upper, -1, true, 0, force / mass / 4});
    } else if (!bodies[lower].awake) {
      // Asleep, the solver holds it as still; awake again, the chain under it gives as it did
      // when it fell asleep. Counted so, a pile does not lose sub-steps as it falls asleep.
      supports_.push_back({upper, lower, true, 0, force / mass});
    } else {
      supports_.push_back({upper, lower, false, bodies[lower].position.dot(up), force / mass});
    }
  }
  // Lowest supports first, so that a body's own give below is complete before it passes it on.
  std::sort(supports_.begin(), supports_.end(), [](const Support& x, const Support& y) {
    return x.lower_known != y.lower_known ? x.lower_known : x.height < y.height;
  });
  // Bodies asleep keep the give below them from when they were awake.
  give_below_.resize(bodies.size(), 0);
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].awake || bodies[i].is_static()) give_below_[i] = 0;
  Real deepest = 0;
  for (const Support& s : supports_) {
    const Real give = (s.lower >= 0 ? give_below_[s.lower] : 0) + s.give;
    give_below_[s.upper] = std::max(give_below_[s.upper], give);
    deepest = std::max(deepest, give);
  }
  // A pile asleep will need its sub-steps again when it wakes; as long as it sleeps they cost
  // little (its contacts are not solved), and a pile that lost them as it fell asleep, its last
  // bodies still awake and softer, would wake itself again.
  for (size_t i = 0; i < bodies.size(); ++i)
    if (!bodies[i].awake && !bodies[i].is_static()) deepest = std::max(deepest, give_below_[i]);
  return deepest;
}

}  // namespace impulse::physics
