#include "physics/sweep_schedule.h"

#include <algorithm>

namespace impulse::physics {

namespace {

// Below this many items a sweep takes a few microseconds: waking helpers would cost as much, and
// the natural order is kept (but for partners).
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

}  // namespace

void SweepSchedule::plan(const std::vector<SweepItem>& items, int body_count, int threads) {
  const size_t count = items.size();
  order_.resize(count);
  slot_of_body_.resize(body_count);
  body_of_slot_.resize(body_count);
  for (int body = 0; body < body_count; ++body) slot_of_body_[body] = body_of_slot_[body] = body;
  lists_.clear();
  enum Part : uint8_t { crossing, left, right, right_after_crossing };
  std::vector<uint8_t> part(count, left);
  if (count < kMinDissectedItems) {
    order_parts(items, part);
    return;
  }

  // The cut: the median of the items' positions along the axis where they spread most.
  Vec3 low = item_position(items[0]), high = low;
  std::vector<Vec3> positions(count);
  for (size_t i = 0; i < count; ++i) {
    positions[i] = item_position(items[i]);
    low = low.cwiseMin(positions[i]);
    high = high.cwiseMax(positions[i]);
  }
  int axis = 0;
  (high - low).maxCoeff(&axis);
  std::vector<Real> keys(count);
  for (size_t i = 0; i < count; ++i) keys[i] = positions[i][axis];
  std::nth_element(keys.begin(), keys.begin() + count / 2, keys.end());
  const Real cut = keys[count / 2];

  // Crossing first, then left, then right, each in the natural order; and of the right ones, those
  // that move a body of a crossing one last: the second thread, which sweeps the right ones, then
  // reaches them when the first has long solved the crossing ones, and need not wait.
  auto side = [&](const Vec3& p) { return p[axis] < cut ? 1 : 2; };
  std::vector<uint8_t> crossed(body_count, 0);
  for (size_t i = 0; i < count; ++i) {
    const SweepItem& item = items[i];
    const int sides = (item.a >= 0 ? side(item.position_a) : 0) | (item.b >= 0 ? side(item.position_b) : 0);
    part[i] = sides == 3 ? crossing : sides == 2 ? right : left;  // both ends still: left
    if (part[i] == crossing) crossed[item.a] = crossed[item.b] = 1;
  }
  for (size_t i = 0; i < count; ++i)
    if (part[i] == right && ((items[i].a >= 0 && crossed[items[i].a]) || (items[i].b >= 0 && crossed[items[i].b]))) part[i] = right_after_crossing;
  order_parts(items, part);
  if (threads < 2) return;

  before_a_.resize(count);
  before_b_.resize(count);
  owner_.resize(count);
  std::vector<int> last(body_count, -1);
  for (size_t place = 0; place < count; ++place) {
    const SweepItem& item = items[order_[place]];
    before_a_[place] = item.a >= 0 ? last[item.a] : -1;
    before_b_[place] = item.b >= 0 ? last[item.b] : -1;
    if (item.a >= 0) last[item.a] = int(place);
    if (item.b >= 0) last[item.b] = int(place);
    owner_[place] = part[order_[place]] >= right ? 1 : 0;
  }
  // Each side's bodies get consecutive slots (those in no manifold go with the first side).
  std::vector<uint8_t> body_owner(body_count, 0);
  for (const SweepItem& item : items) {
    if (item.a >= 0) body_owner[item.a] = side(item.position_a) == 2;
    if (item.b >= 0) body_owner[item.b] = side(item.position_b) == 2;
  }
  int next_slot = 0;
  for (int owner = 0; owner < 2; ++owner) {
    if (owner == 1) slot_split_ = next_slot;
    for (int body = 0; body < body_count; ++body)
      if (body_owner[body] == owner) slot_of_body_[body] = next_slot++;
  }
  for (int body = 0; body < body_count; ++body) body_of_slot_[slot_of_body_[body]] = body;
  lists_.assign(2, {});
  rank_in_list_.resize(count);
  for (size_t place = 0; place < count; ++place) {
    rank_in_list_[place] = uint32_t(lists_[owner_[place]].size());
    lists_[owner_[place]].push_back(int(place));
  }
  awaited_.assign(count, 0);
  for (size_t place = 0; place < count; ++place)
    for (int before : {before_a_[place], before_b_[place]})
      if (before >= 0 && owner_[before] != owner_[place]) awaited_[before] = 1;
  if (!progress_) progress_ = std::make_unique<Progress[]>(2);
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
  const std::atomic<uint64_t>& progress = progress_[owner_[place]].value;
  Backoff backoff;
  while (progress.load(std::memory_order_acquire) < target) backoff.pause();
}

}  // namespace impulse::physics
