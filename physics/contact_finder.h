// Finds this step's contacts: a broad phase proposes pairs, the narrow phase (collide.h) gives
// their contact points, or, for a pair of boxes that have not moved relative to each other since
// they were built (within 0.1 um, kRecycleDistance), the same contacts again, carried by body A's motion
// (contact recycling, Box2D v3.2's).
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
  // increasing order of (i, j), as a loop over all pairs would give them, however many of
  // `team`'s threads share the broad and narrow phase (at most `threads`): on a first call the
  // same bits; after it, a recycled pair's contacts differ from a fresh narrow phase's by less
  // than kRecycleDistance (and are the same whatever the threads).
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

  // Contact recycling (Box2D v3.2's): a pair whose bodies have barely moved relative to each
  // other since its contacts were built gets those contacts again, carried by body A's motion,
  // instead of the narrow phase. Each pair's contacts when built, in A's frame; the contacts
  // themselves in the list of the thread that built them.
  struct LocalContact {
    Vec3 point = Vec3::Zero();  // in A's frame
    Real separation = 0;
    uint32_t feature = 0;
    bool swapped = false;       // the contact's body_a is the pair's b
  };
  struct Built {
    Quat relative_orientation = Quat::Identity();    // A^-1 B (first: it aligns to 16 bytes)
    Vec3 relative_position = Vec3::Zero();           // B's centre in A's frame
    Vec3 normal = Vec3::Zero();                      // in A's frame, shared by the pair's contacts
    Real margin = -1;                                // the speculative margin they were built with
    int first = 0;                                   // its contacts, in its thread's local_
    int count = 0;
  };
  struct BuiltRef {                                  // where a pair's Built is
    int16_t thread = -1;                             // -1: nothing to recycle
    int index = 0;                                   // in records_[thread]
  };
  std::vector<BuiltRef> built_, previous_built_;     // pairs_[k]'s; last call's
  std::vector<std::vector<Built>> records_, previous_records_;  // per thread
  std::vector<std::vector<LocalContact>> local_, previous_local_;  // per thread
  std::vector<size_t> recycled_per_thread_;
  size_t recycled_ = 0;                              // pairs recycled by the last call
  static Built relative_pose(const Body& a, const Body& b);
  bool recycle(const std::vector<Body>& bodies, const BodyPair& pair, Real margin, BuiltRef& ref, int thread,
               std::vector<Contact>& contacts);
  void note_built(const std::vector<Body>& bodies, const BodyPair& pair, Real margin, const std::vector<Contact>& contacts,
                  size_t first, BuiltRef& ref, int thread);

 public:
  size_t recycled_pairs() const { return recycled_; }  // by the last find()
};

// Farthest a body's surface can travel in dt: bounds the speculative margin.
Real motion_bound(const Body& body, Real dt);

}  // namespace impulse::physics
