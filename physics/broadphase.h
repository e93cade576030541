// Broad phase: the pairs of bodies whose bounding boxes overlap, by sweep and prune.
#pragma once
#include "physics/body.h"
#include "physics/thread_team.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

// An axis-aligned box; a plane's is unbounded (infinite on every side).
struct Aabb {
  Vec3 lower, upper;
};

inline bool overlap(const Aabb& a, const Aabb& b) {
  return a.lower.x() <= b.upper.x() && b.lower.x() <= a.upper.x() && a.lower.y() <= b.upper.y() &&
         b.lower.y() <= a.upper.y() && a.lower.z() <= b.upper.z() && b.lower.z() <= a.upper.z();
}

// The world-space box around a body's shape, grown by `margin` on every side.
Aabb body_aabb(const Body& body, Real margin);

struct BodyPair {
  int a, b;  // a < b
  bool operator==(const BodyPair&) const = default;
};

// Sweep and prune along the axis on which the boxes' centres vary most: sorted by their lower
// bound there, each box is tested only against those that start before it ends. Measured on a
// 1000-box heap and a 5050-box pyramid it beat a uniform grid and a rebuilt AABB tree. The only
// state kept between calls is last call's order, from which this call's sorts in a few moves.
class BroadPhase {
 public:
  // Every pair (i < j) whose boxes overlap and of which at least one is active (active[i] != 0),
  // in increasing order of (i, j) whatever the boxes, so that contacts come out the same every run.
  // With a team, its threads share the sweep (the pairs are the same).
  void find_pairs(const std::vector<Aabb>& boxes, const std::vector<uint8_t>& active, std::vector<BodyPair>& pairs,
                  ThreadTeam* team = nullptr);

 private:
  void sort_entries(const std::vector<Aabb>& boxes, const std::vector<uint8_t>& active, int axis);

  struct Entry {
    Real lower, upper;                      // along the sweep axis
    Real lower1, upper1, lower2, upper2;    // along the other two
    int body;
    int active;
  };
  std::vector<Entry> entries_;
  std::vector<int> order_;                    // last call's bodies in sweep order
  int order_axis_ = -1;                       // and its axis
  // Each thread's pairs, unsorted. A line of its own each: a push_back writes the vector's end,
  // and two threads writing one line would pass it back and forth at every pair.
  struct alignas(64) Found {
    std::vector<BodyPair> pairs;
  };
  std::vector<Found> found_;
  std::vector<int> starts_;
};

}  // namespace impulse::physics
