#include "physics/stack_sink.h"

#include <algorithm>

namespace impulse::physics {

Real StackSink::deepest_give(const ContactSolver& solver, const std::vector<BodyState>& states, const std::vector<Body>& bodies,
                             const Vec3& up, Real h) {
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
    const int upper = a_above ? m.a : m.b, lower = a_above ? m.b : m.a;
    // A contact with a body that does not move is twice as stiff (staticSoftness): a quarter the give.
    if (states[lower].inv_mass == 0) supports_.push_back({body_of_slot[upper], -1, 0, force / mass / 4});
    else supports_.push_back({body_of_slot[upper], body_of_slot[lower], bodies[body_of_slot[lower]].position.dot(up), force / mass});
  }
  // Lowest supports first, so that a body's own give below is complete before it passes it on.
  std::sort(supports_.begin(), supports_.end(), [](const Support& x, const Support& y) {
    return (x.lower < 0) != (y.lower < 0) ? x.lower < 0 : x.height < y.height;
  });
  give_below_.assign(bodies.size(), 0);
  Real deepest = 0;
  for (const Support& s : supports_) {
    const Real give = (s.lower >= 0 ? give_below_[s.lower] : 0) + s.give;
    give_below_[s.upper] = std::max(give_below_[s.upper], give);
    deepest = std::max(deepest, give);
  }
  return deepest;
}

}  // namespace impulse::physics
