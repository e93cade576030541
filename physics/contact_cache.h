// Contacts of box pairs that have hardly moved against each other since they were computed, kept
// from step to step (Bullet keeps its persistent manifolds the same way): the separating-axis test
// and the clipping are most of the narrow phase, and a pile at rest asks the same question every
// step. The kept points move with the bodies, and their separations are measured anew.
#pragma once
#include "physics/body.h"
#include "physics/contact.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

class ContactCache {
 public:
  // A new step, whose pairs `threads` threads share, each in increasing order.
  void begin(int threads);
  // Appends the contacts of boxes a and b (ia < ib) whose separation is below `margin`, as
  // collide_boxes() does: last step's, if still good, else computed anew.
  void collide_boxes(const Body& a, int ia, const Body& b, int ib, Real margin, int thread, std::vector<Contact>& out);
  // This step's pairs become the ones the next step looks in.
  void end();

 private:
  struct Entry {
    uint64_t key;                      // the pair
    Quat relative_orientation;         // B's in A's frame, when computed
    Vec3 relative_position;            // B's centre in A's frame, when computed
    int first, count;                  // its points, in its share's
  };
  struct Point {
    Vec3 on_a, on_b;                   // each surface's point, in its body's frame
    Vec3 normal;                       // in A's frame
    uint32_t feature;
  };
  struct alignas(64) Share {  // one thread's, each on cache lines of its own
    std::vector<Entry> entries;
    std::vector<Point> points;
    int search_share = -1;             // where this thread looks in last step's shares next
    size_t search_place = 0;
  };
  const Entry* find(uint64_t key, Share& share) const;

  std::vector<Share> current_, previous_;
};

}  // namespace impulse::physics
