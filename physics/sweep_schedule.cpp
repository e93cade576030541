#include "physics/sweep_schedule.h"

#include <algorithm>

namespace impulse::physics {

namespace {

// Below this many items a part takes a few microseconds to sweep: it is not cut, and a set this
// small keeps its natural order (but for partners) and one thread.
constexpr size_t kMinDissectedItems = 256;
// How far ahead in its part an item's partner may be: near, so that the sweep keeps its order and
// its place in memory roughly.
constexpr size_t kPartnerReach = 16;

bool share_a_body(const SweepItem& x, const SweepItem& y) {
  return (x.a >= 0 && (x.a == y.a || x.a == y.b)) || (x.b >= 0 && (x.b == y.a || x.b == y.b));
}

Vec3 item_position(const SweepItem& item) {
  if (item.a >= 0 && item.b >= 0) return (item.position_a + item.position_b) / 2;
  return item.a >= 0 ? item.position_a : item.position_b;
}

// The dissection tree as parts numbered in the sweep's order (depth first: a node's crossing
// items, its left subtree, its right subtree; a leaf's free items, then those that move a body of
// a crossing item), and for each part the leaf whose thread sweeps it (for crossing items, the
// first leaf of the node's subtree). The first leaf is not split: its thread sweeps every crossing
// part before it anyway.
struct Dissection {
  const std::vector<SweepItem>& items;
  int levels;
  std::vector<uint8_t> part;            // per item
  std::vector<int> leaf_of_part;
  std::vector<uint8_t> is_crossing;     // per part
  std::vector<uint8_t> crossed;         // per body: moved by a crossing item
  int leaves = 0;

  Dissection(const std::vector<SweepItem>& all, int body_count, int most_levels)
      : items(all), levels(most_levels), part(all.size(), 0), crossed(body_count, 0) {}

  int new_part(int leaf, bool crossing) {
    leaf_of_part.push_back(leaf);
    is_crossing.push_back(crossing);
    return int(leaf_of_part.size()) - 1;
  }

  void cut(const std::vector<int>& members, int level) {
    if (level > levels || members.size() < kMinDissectedItems) {
      const int leaf = leaves++, free = new_part(leaf, false), after_crossing = new_part(leaf, false);
      for (const int i : members) {
        const SweepItem& item = items[i];
        const bool waits = leaf > 0 && ((item.a >= 0 && crossed[item.a]) || (item.b >= 0 && crossed[item.b]));
        part[i] = uint8_t(waits ? after_crossing : free);
      }
      return;
    }
    // The cut: the median of the members' positions along the axis where they spread most.
    Vec3 low = item_position(items[members[0]]), high = low;
    for (const int i : members) {
      low = low.cwiseMin(item_position(items[i]));
      high = high.cwiseMax(item_position(items[i]));
    }
    int axis = 0;
    (high - low).maxCoeff(&axis);
    std::vector<Real> keys(members.size());
    for (size_t k = 0; k < members.size(); ++k) keys[k] = item_position(items[members[k]])[axis];
    std::nth_element(keys.begin(), keys.begin() + keys.size() / 2, keys.end());
    const Real median = keys[keys.size() / 2];
    auto side = [&](const Vec3& p) { return p[axis] < median ? 1 : 2; };

    const int crossing = new_part(leaves, true);
    std::vector<int> left, right;
    for (const int i : members) {
      const SweepItem& item = items[i];
      const int sides = (item.a >= 0 ? side(item.position_a) : 0) | (item.b >= 0 ? side(item.position_b) : 0);
      if (sides == 3) {
        part[i] = uint8_t(crossing);
        crossed[item.a] = crossed[item.b] = 1;
      } else {
        (sides == 2 ? right : left).push_back(i);  // both ends still: left
      }
    }
    cut(left, level + 1);
    cut(right, level + 1);
  }
};

}  // namespace

void SweepSchedule::plan(const std::vector<SweepItem>& items, int body_count, int threads, int levels) {
  const size_t count = items.size();
  order_.resize(count);
  slot_of_body_.resize(body_count);
  body_of_slot_.resize(body_count);
  for (int body = 0; body < body_count; ++body) slot_of_body_[body] = body_of_slot_[body] = body;
  lists_.clear();
  team_size_ = threads;
  Dissection dissection(items, body_count, std::clamp(levels, 1, 7));
  std::vector<int> all(count);
  for (size_t i = 0; i < count; ++i) all[i] = int(i);
  dissection.cut(all, 1);
  order_parts(items, dissection.part);
  const int sharing = std::min(threads, dissection.leaves);
  if (sharing < 2) return;

  // Runs of consecutive leaves, as even in items as they can be: a leaf goes to the thread in
  // whose share of the items its middle falls.
  std::vector<size_t> leaf_items(dissection.leaves, 0);
  for (size_t i = 0; i < count; ++i) ++leaf_items[dissection.leaf_of_part[dissection.part[i]]];
  std::vector<int> thread_of_leaf(dissection.leaves);
  size_t before = 0;
  for (int leaf = 0; leaf < dissection.leaves; ++leaf) {
    thread_of_leaf[leaf] = int(std::min<size_t>(sharing - 1, (2 * before + leaf_items[leaf]) * sharing / (2 * count)));
    before += leaf_items[leaf];
  }
  std::vector<int> thread_of_part(dissection.leaf_of_part.size());
  for (size_t p = 0; p < thread_of_part.size(); ++p) thread_of_part[p] = thread_of_leaf[dissection.leaf_of_part[p]];
  share(items, dissection.part, thread_of_part, dissection.is_crossing, sharing);
}

// Each place's owner, the places before it that move its bodies, and whether another thread waits
// for it; each thread's bodies get consecutive slots.
void SweepSchedule::share(const std::vector<SweepItem>& items, const std::vector<uint8_t>& part,
                          const std::vector<int>& thread_of_part, const std::vector<uint8_t>& is_crossing, int threads) {
  const size_t count = items.size();
  const int body_count = int(slot_of_body_.size());
  before_a_.resize(count);
  before_b_.resize(count);
  owner_.resize(count);
  std::vector<int> last(body_count, -1);
  // A body goes with the thread of its leaf: of a leaf's item that moves it, else of the first
  // crossing item that does (in none: the first thread).
  std::vector<int> body_owner(body_count, -1);
  for (size_t place = 0; place < count; ++place) {
    const SweepItem& item = items[order_[place]];
    const int owner = thread_of_part[part[order_[place]]];
    before_a_[place] = item.a >= 0 ? last[item.a] : -1;
    before_b_[place] = item.b >= 0 ? last[item.b] : -1;
    for (const int body : {item.a, item.b}) {
      if (body < 0) continue;
      last[body] = int(place);
      if (body_owner[body] < 0 || !is_crossing[part[order_[place]]]) body_owner[body] = owner;
    }
    owner_[place] = uint8_t(owner);
  }
  int next_slot = 0;
  slot_begin_.assign(threads + 1, 0);
  for (int owner = 0; owner < threads; ++owner) {
    slot_begin_[owner] = next_slot;
    for (int body = 0; body < body_count; ++body)
      if (std::max(body_owner[body], 0) == owner) slot_of_body_[body] = next_slot++;
  }
  slot_begin_[threads] = next_slot;
  for (int body = 0; body < body_count; ++body) body_of_slot_[slot_of_body_[body]] = body;
  lists_.assign(threads, {});
  rank_in_list_.resize(count);
  for (size_t place = 0; place < count; ++place) {
    rank_in_list_[place] = uint32_t(lists_[owner_[place]].size());
    lists_[owner_[place]].push_back(int(place));
  }
  awaited_.assign(count, 0);
  for (size_t place = 0; place < count; ++place)
    for (int before : {before_a_[place], before_b_[place]})
      if (before >= 0 && owner_[before] != owner_[place]) awaited_[before] = 1;
  if (progress_count_ < threads) {  // the counters only grow: a sweep's epoch is newer than any value
    progress_ = std::make_unique<WaitableCounter[]>(threads);
    progress_count_ = threads;
  }
}

// The order: part after part, each in the items' order but for partners. An item's partner is the
// first one after it, not yet placed and not too far, with as many points and no moving body in
// common; it comes right after it, and the two are solved side by side.
void SweepSchedule::order_parts(const std::vector<SweepItem>& items, const std::vector<uint8_t>& part) {
  const size_t count = items.size();
  paired_.assign(count, 0);
  std::vector<uint8_t> placed(count, 0);
  std::vector<int> members;
  int next = 0;
  const uint8_t last_part = count == 0 ? 0 : *std::max_element(part.begin(), part.end());
  for (uint8_t group = 0; group <= last_part; ++group) {
    members.clear();
    for (size_t i = 0; i < count; ++i)
      if (part[i] == group) members.push_back(int(i));
    for (size_t p = 0; p < members.size(); ++p) {
      const int i = members[p];
      if (placed[i]) continue;
      placed[i] = 1;
      order_[next++] = i;
      if (items[i].size == 0) continue;
      for (size_t q = p + 1; q < members.size() && q <= p + kPartnerReach; ++q) {
        const int j = members[q];
        if (placed[j] || items[j].size != items[i].size || share_a_body(items[i], items[j])) continue;
        placed[j] = 1;
        paired_[next - 1] = 1;
        order_[next++] = j;
        break;
      }
    }
  }
}

void SweepSchedule::wait_for(int place, int thread, uint64_t epoch) const {
  if (place < 0 || owner_[place] == thread) return;
  const uint64_t target = (epoch << kEpochShift) + rank_in_list_[place] + 1;
  progress_[owner_[place]].wait_until_at_least(target, team_size_);
}

}  // namespace impulse::physics
