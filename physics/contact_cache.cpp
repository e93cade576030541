#include "physics/contact_cache.h"

#include "physics/collide.h"

#include <algorithm>

namespace impulse::physics {

namespace {

// How far two boxes may move against each other before their contacts are computed anew: far less
// than a contact's give under load, and a pile at rest moves microns.
constexpr Real kMaxShift = Real(0.5e-3);      // m, B's centre in A's frame
constexpr Real kMaxHalfTurn = Real(0.25e-3);  // sine of half the angle B has turned in A's frame

uint64_t key_of(int ia, int ib) { return (uint64_t(uint32_t(ia)) << 32) | uint32_t(ib); }

}  // namespace

void ContactCache::begin(int threads) {
  current_.resize(threads);
  for (Share& share : current_) {
    share.entries.clear();
    share.points.clear();
    share.search_share = -1;
  }
}

void ContactCache::end() { std::swap(current_, previous_); }

// Last step's entry for the pair, if any. A thread's keys come in increasing order, so each search
// goes on from where the last one stopped; the thread's first of a step starts by bisection.
const ContactCache::Entry* ContactCache::find(uint64_t key, Share& share) const {
  if (share.search_share < 0) {
    share.search_share = 0;
    for (int s = 1; s < int(previous_.size()); ++s)
      if (!previous_[s].entries.empty() && previous_[s].entries.front().key <= key) share.search_share = s;
    share.search_place = 0;
    if (!previous_.empty()) {
      const std::vector<Entry>& entries = previous_[share.search_share].entries;
      share.search_place = size_t(std::lower_bound(entries.begin(), entries.end(), key, [](const Entry& e, uint64_t k) { return e.key < k; }) -
                                  entries.begin());
    }
  }
  while (share.search_share < int(previous_.size())) {
    const std::vector<Entry>& entries = previous_[share.search_share].entries;
    while (share.search_place < entries.size() && entries[share.search_place].key < key) ++share.search_place;
    if (share.search_place < entries.size()) return entries[share.search_place].key == key ? &entries[share.search_place] : nullptr;
    ++share.search_share;
    share.search_place = 0;
  }
  return nullptr;
}

void ContactCache::collide_boxes(const Body& a, int ia, const Body& b, int ib, Real margin, int thread, std::vector<Contact>& out) {
  Share& share = current_[thread];
  const uint64_t key = key_of(ia, ib);
  const Quat to_a = a.orientation.conjugate();
  const Quat relative_orientation = to_a * b.orientation;
  const Vec3 relative_position = to_a * (b.position - a.position);
  if (const Entry* kept = find(key, share)) {
    const Quat turn = relative_orientation * kept->relative_orientation.conjugate();
    if ((relative_position - kept->relative_position).norm() < kMaxShift && turn.vec().norm() < kMaxHalfTurn) {
      const std::vector<Point>& points = previous_[share.search_share].points;
      const size_t start = out.size();
      bool good = true;
      for (int i = 0; i < kept->count && good; ++i) {
        const Point& p = points[kept->first + i];
        const Vec3 normal = a.orientation * p.normal;
        const Vec3 on_a = a.position + a.orientation * p.on_a;
        const Vec3 on_b = b.position + b.orientation * p.on_b;
        const Real separation = (on_a - on_b).dot(normal);
        good = separation <= margin;  // else the point would have left the manifold: ask anew
        out.push_back({ia, ib, (on_a + on_b) / 2, normal, separation, p.feature});
      }
      if (good) {
        share.entries.push_back({key, kept->relative_orientation, kept->relative_position, int(share.points.size()), kept->count});
        share.points.insert(share.points.end(), points.begin() + kept->first, points.begin() + kept->first + kept->count);
        return;
      }
      out.resize(start);
    }
  }
  // Anew: each point's two surface points, P -+ n s / 2, kept in the bodies' frames.
  const size_t start = out.size();
  physics::collide_boxes(a, ia, b, ib, margin, out);
  share.entries.push_back({key, relative_orientation, relative_position, int(share.points.size()), int(out.size() - start)});
  const Quat to_b = b.orientation.conjugate();
  for (size_t k = start; k < out.size(); ++k) {
    const Contact& c = out[k];
    const Vec3 half = c.normal * (c.separation / 2);
    share.points.push_back({to_a * (c.point + half - a.position), to_b * (c.point - half - b.position), to_a * c.normal, c.feature});
  }
}

}  // namespace impulse::physics
