#include "physics/sweep_schedule.h"

#include <algorithm>

namespace impulse::physics {

namespace {

// Below this many items a sweep takes a few microseconds: waking helpers would cost as much, and
// the natural order is kept.
constexpr size_t kMinDissectedItems = 256;

Vec3 item_position(const SweepItem& item) {
  if (item.a >= 0 && item.b >= 0) return (item.position_a + item.position_b) / 2;
  return item.a >= 0 ? item.position_a : item.position_b;
}

}  // namespace

void SweepSchedule::plan(const std::vector<SweepItem>& items, int body_count, int threads) {
  const size_t count = items.size();
  order_.resize(count);
  for (size_t i = 0; i < count; ++i) order_[i] = int(i);
  slot_of_body_.resize(body_count);
  body_of_slot_.resize(body_count);
  for (int body = 0; body < body_count; ++body) slot_of_body_[body] = body_of_slot_[body] = body;
  lists_.clear();
  if (count < kMinDissectedItems) return;

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
  enum Part : uint8_t { crossing, left, right, right_after_crossing };
  std::vector<uint8_t> part(count), crossed(body_count, 0);
  for (size_t i = 0; i < count; ++i) {
    const SweepItem& item = items[i];
    const int sides = (item.a >= 0 ? side(item.position_a) : 0) | (item.b >= 0 ? side(item.position_b) : 0);
    part[i] = sides == 3 ? crossing : sides == 2 ? right : left;  // both ends still: left
    if (part[i] == crossing) crossed[item.a] = crossed[item.b] = 1;
  }
  for (size_t i = 0; i < count; ++i)
    if (part[i] == right && ((items[i].a >= 0 && crossed[items[i].a]) || (items[i].b >= 0 && crossed[items[i].b]))) part[i] = right_after_crossing;
  int next = 0;
  for (uint8_t group = crossing; group <= right_after_crossing; ++group)
    for (size_t i = 0; i < count; ++i)
      if (part[i] == group) order_[next++] = int(i);
  if (threads < 2) return;

  before_a_.resize(count);
  before_b_.resize(count);
  owner_.resize(count);
  std::vector<int> last(body_count, -1);
  for (size_t step = 0; step < count; ++step) {
    const SweepItem& item = items[order_[step]];
    before_a_[step] = item.a >= 0 ? last[item.a] : -1;
    before_b_[step] = item.b >= 0 ? last[item.b] : -1;
    if (item.a >= 0) last[item.a] = int(step);
    if (item.b >= 0) last[item.b] = int(step);
    owner_[step] = part[order_[step]] >= right ? 1 : 0;
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
  place_.resize(count);
  for (size_t step = 0; step < count; ++step) {
    place_[step] = uint32_t(lists_[owner_[step]].size());
    lists_[owner_[step]].push_back(int(step));
  }
  awaited_.assign(count, 0);
  for (size_t step = 0; step < count; ++step)
    for (int before : {before_a_[step], before_b_[step]})
      if (before >= 0 && owner_[before] != owner_[step]) awaited_[before] = 1;
  if (!progress_) progress_ = std::make_unique<Progress[]>(2);
}

void SweepSchedule::wait_for(int step, int thread, uint64_t epoch) const {
  if (step < 0 || owner_[step] == thread) return;
  const uint64_t target = (epoch << kEpochShift) + place_[step] + 1;
  const std::atomic<uint64_t>& progress = progress_[owner_[step]].value;
  Backoff backoff;
  while (progress.load(std::memory_order_acquire) < target) backoff.pause();
}

}  // namespace impulse::physics
