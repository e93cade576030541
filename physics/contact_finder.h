// Finds this step's contacts: a broad phase proposes pairs, the narrow phase (collide.h) gives
// their contact points.
#pragma once
#include "physics/body.h"
#include "physics/broadphase.h"
#include "physics/collide.h"
#include "physics/contact.h"
#include "physics/thread_team.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

class ContactFinder {
 public:
  // Appends the contacts of every pair in which at least one body is awake (awake[i] != 0;
  // static bodies are never awake) into `out` (cleared first). A pair's speculative margin is
  // base_margin plus how far each body can move in dt. The contacts come pair by pair in
  // increasing order of (i, j), exactly as a loop over all pairs would give them, however many
  // of `team`'s threads share the broad and narrow phase (at most `threads`).
  void find(const std::vector<Body>& bodies, const std::vector<uint8_t>& awake, Real dt, Real base_margin,
            ThreadTeam& team, int threads, std::vector<Contact>& out);

 private:
  BroadPhase broad_phase_;
  std::vector<Aabb> boxes_;
  std::vector<Real> motion_bounds_;
  std::vector<BodyPair> pairs_;
  std::vector<std::vector<Contact>> shares_;  // each helper thread's contacts, in pair order
  std::vector<SatCache> caches_;              // pairs_[k]'s
  std::vector<BodyPair> previous_pairs_;      // last call's pairs, in order, and their caches
  std::vector<SatCache> previous_caches_;
};

// Farthest a body's surface can travel in dt: bounds the speculative margin.
Real motion_bound(const Body& body, Real dt);

}  // namespace impulse::physics
