#include "physics/stack_sink.h"

#include <algorithm>

namespace impulse::physics {

bool moving_overlap_too_deep(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, Real overlap, Real speed) {
  auto moving = [&](const Body& body) {
    return !body.is_static() && body.velocity.norm() + body.angular_velocity.norm() * bounding_radius(body.shape) > speed;
  };
  for (const Contact& c : contacts) {
    if (c.separation >= 0) continue;
    const Body& a = bodies[c.body_a];
    const Body& b = bodies[c.body_b];
    const Real thinnest = 2 * std::min(thinnest_half_size(a.shape), thinnest_half_size(b.shape));
    if (-c.separation > std::min(overlap, thinnest / 20) && (moving(a) || moving(b))) return true;
  }
  return false;
}

Real StackSink::deepest_give(const ContactSolver& solver, const std::vector<Body>& bodies, const Vec3& up, Real h) {
  const auto& body_of_slot = solver.body_of_slot();
  const int n = int(bodies.size());
  // Bodies asleep keep the give below them from when they were awake.
  give_below_.resize(n, 0);
  for (int i = 0; i < n; ++i)
    if (bodies[i].awake || bodies[i].is_static()) give_below_[i] = 0;
  // A body on several supports sinks by their gives averaged with their loads as weights: the
  // lever rule (a body on two supports at distances d1, d2 from its centre carries F d2 / (d1 + d2)
  // on the first, and its centre sinks by d2 / (d1 + d2) of the first support's give plus d1 /
  // (d1 + d2) of the second's). Supports on a still body (static or asleep) start the chains: the
  // give below them is known.
  weighted_.assign(n, 0);
  weight_.assign(n, 0);
  supports_.clear();
  for (const ManifoldLoad& load : solver.loads()) {
    if (load.impulse <= 0 || load.normal_mass <= 0) continue;
    const bool a_above = load.normal.dot(up) > 0;  // the normal points from B to A
    const int upper = body_of_slot[a_above ? load.a : load.b], lower = body_of_slot[a_above ? load.b : load.a];
    const Real give = load.impulse / h / load.normal_mass;
    if (bodies[lower].is_static()) {
      weighted_[upper] += load.impulse * give;
      weight_[upper] += load.impulse;
    } else if (!bodies[lower].awake) {
      // Asleep, the solver holds it as still; awake again, the chain under it gives as it did
      // when it fell asleep. Counted so, a pile does not lose sub-steps as it falls asleep.
      weighted_[upper] += load.impulse * (give_below_[lower] + give);
      weight_[upper] += load.impulse;
    } else {
      supports_.push_back({upper, lower, give, load.impulse});
    }
  }
  auto settle = [&](int body) {
    if (weight_[body] > 0) give_below_[body] = weighted_[body] / weight_[body];
  };
  // The chains between moving bodies, each body once all the supports under it are counted (Kahn's
  // topological order).
  unsupported_below_.assign(n, 0);
  first_above_.assign(n + 1, 0);
  for (const Support& s : supports_) {
    ++unsupported_below_[s.upper];
    ++first_above_[s.lower + 1];
  }
  for (int i = 0; i < n; ++i) first_above_[i + 1] += first_above_[i];
  above_.resize(supports_.size());
  next_above_.assign(first_above_.begin(), first_above_.end() - 1);
  for (const Support& s : supports_) above_[next_above_[s.lower]++] = &s - supports_.data();
  ready_.clear();
  for (int i = 0; i < n; ++i)
    if (unsupported_below_[i] == 0) {
      settle(i);
      ready_.push_back(i);
    }
  for (size_t k = 0; k < ready_.size(); ++k) {
    const int lower = ready_[k];
    for (int e = first_above_[lower]; e < first_above_[lower + 1]; ++e) {
      const Support& s = supports_[above_[e]];
      weighted_[s.upper] += s.load * (give_below_[lower] + s.give);
      weight_[s.upper] += s.load;
      if (--unsupported_below_[s.upper] == 0) {
        settle(s.upper);
        ready_.push_back(s.upper);
      }
    }
  }
  // Bodies leaning on each other in a ring (no order exists) pass their give on once.
  if (int(ready_.size()) < n) {
    for (const Support& s : supports_)
      if (unsupported_below_[s.lower] > 0) {
        weighted_[s.upper] += s.load * (give_below_[s.lower] + s.give);
        weight_[s.upper] += s.load;
      }
    for (int i = 0; i < n; ++i)
      if (unsupported_below_[i] > 0) settle(i);
  }
  // A pile asleep will need its sub-steps again when it wakes; as long as it sleeps they cost
  // little (its contacts are not solved), and a pile that lost them as it fell asleep, its last
  // bodies still awake and softer, would wake itself again.
  Real deepest = 0;
  for (int i = 0; i < n; ++i)
    if (!bodies[i].is_static()) deepest = std::max(deepest, give_below_[i]);
  return deepest;
}

}  // namespace impulse::physics
