// Contacts of a step: sweep-and-prune pairs, then the narrow phase on each.
#include "physics/contact_finder.h"

#include "physics/collide.h"

#include <algorithm>

namespace impulse::physics {

Real motion_bound(const Body& body, Real dt) {
  return (body.velocity.norm() + body.angular_velocity.norm() * bounding_radius(body.shape)) * dt;
}

namespace {

// Fewer pairs than this are not worth waking a helper for.
constexpr size_t kMinPairsPerThread = 128;

}  // namespace

void ContactFinder::find(const std::vector<Body>& bodies, const std::vector<uint8_t>& awake, Real dt,
                         Real base_margin, ThreadTeam& team, int team_threads, std::vector<Contact>& out) {
  out.clear();
  // Each box grows by its body's share of a pair's margin, so that two boxes overlap whenever
  // their shapes are within base_margin + motion_bound(a) + motion_bound(b).
  const size_t n = bodies.size();
  boxes_.resize(n);
  motion_bounds_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    motion_bounds_[i] = motion_bound(bodies[i], dt);
    boxes_[i] = body_aabb(bodies[i], base_margin / 2 + motion_bounds_[i]);
  }
  broad_phase_.find_pairs(boxes_, awake, pairs_, team_threads > 1 ? &team : nullptr);
  // Each pair starts from last call's cache (both lists in increasing pair order: one merge).
  caches_.assign(pairs_.size(), SatCache{});
  auto before = [](const BodyPair& x, const BodyPair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
  for (size_t k = 0, p = 0; k < pairs_.size(); ++k) {
    while (p < previous_pairs_.size() && before(previous_pairs_[p], pairs_[k])) ++p;
    if (p < previous_pairs_.size() && previous_pairs_[p] == pairs_[k]) caches_[k] = previous_caches_[p];
  }
  auto collide_range = [&](size_t begin, size_t end, std::vector<Contact>& contacts) {
    for (size_t k = begin; k < end; ++k) {
      const BodyPair& pair = pairs_[k];
      const Real margin = base_margin + motion_bounds_[pair.a] + motion_bounds_[pair.b];
      collide(bodies[pair.a], pair.a, bodies[pair.b], pair.b, margin, contacts, &caches_[k]);
    }
  };
  const size_t threads = std::min({size_t(team.size()), size_t(std::max(team_threads, 1)), pairs_.size() / kMinPairsPerThread});
  if (threads < 2) {
    collide_range(0, pairs_.size(), out);
  } else {
    // Consecutive runs of pairs, one per thread, joined in order afterwards.
    shares_.resize(threads - 1);
    team.run([&](int thread) {
      if (size_t(thread) >= threads) return;
      std::vector<Contact>& contacts = thread == 0 ? out : shares_[thread - 1];
      contacts.clear();
      collide_range(pairs_.size() * thread / threads, pairs_.size() * (thread + 1) / threads, contacts);
    });
    for (const std::vector<Contact>& share : shares_) out.insert(out.end(), share.begin(), share.end());
  }
  std::swap(previous_pairs_, pairs_);  // pairs_ is refilled by the next call's broad phase
  std::swap(previous_caches_, caches_);
}

}  // namespace impulse::physics
