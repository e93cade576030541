// Sweep and prune on the axis of largest variance, with the pairs put in (i, j) order.
#include "physics/broadphase.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

namespace impulse::physics {

Aabb body_aabb(const Body& body, Real margin) {
  if (body.shape.type == ShapeType::plane) {
    const Real inf = std::numeric_limits<Real>::infinity();
    return {Vec3::Constant(-inf), Vec3::Constant(inf)};
  }
  const Shape& s = body.shape;
  if (s.type == ShapeType::mesh) {  // its tree's box (the slabs behind the triangles too), turned
    const Mat3 rotation = body.orientation.toRotationMatrix();
    const MeshNode& root = s.mesh()->nodes[0];
    Vec3 low = Vec3::Constant(std::numeric_limits<Real>::infinity()), high = -low;
    for (int k = 0; k < 8; ++k) {
      const Vec3 x = rotation * Vec3(k & 1 ? root.high.x() : root.low.x(), k & 2 ? root.high.y() : root.low.y(),
                                     k & 4 ? root.high.z() : root.low.z());
      low = low.cwiseMin(x), high = high.cwiseMax(x);
    }
    return {body.position + low - Vec3::Constant(margin), body.position + high + Vec3::Constant(margin)};
  }
  if (s.type == ShapeType::hull) {  // not symmetric: its corners' extremes
    const Mat3 rotation = body.orientation.toRotationMatrix();
    Vec3 low = Vec3::Constant(std::numeric_limits<Real>::infinity()), high = -low;
    for (const Vec3& p : s.hull()->corners) {
      const Vec3 x = rotation * p;
      low = low.cwiseMin(x), high = high.cwiseMax(x);
    }
    return {body.position + low - Vec3::Constant(margin), body.position + high + Vec3::Constant(margin)};
  }
  Vec3 reach = Vec3::Constant(s.radius);
  if (s.type == ShapeType::box) {
    reach = body.orientation.toRotationMatrix().cwiseAbs() * s.half_extents;
  } else if (s.type != ShapeType::sphere) {
    for (int k = 0; k < 3; ++k) reach[k] = reach_along(s, body.orientation, Vec3::Unit(k));
  }
  reach += Vec3::Constant(margin);
  return {body.position - reach, body.position + reach};
}

namespace {

constexpr int kMinBodiesPerThread = 256;  // fewer: not worth waking a helper for
constexpr int kEntriesPerRun = 64;

}  // namespace

// The entries by lower bound along `axis`, ties by body. From last call's order when it swept the
// same bodies along the same axis: bodies move little in a step, so an insertion sort has little
// to do. When it would have much (a fast scatter), std::sort instead.
void BroadPhase::sort_entries(const std::vector<Aabb>& boxes, const std::vector<uint8_t>& active, int axis) {
  const int n = int(boxes.size()), axis1 = (axis + 1) % 3, axis2 = (axis + 2) % 3;
  if (axis != order_axis_ || int(order_.size()) != n) {
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    order_axis_ = axis;
  }
  entries_.resize(n);
  for (int k = 0; k < n; ++k) {
    const int i = order_[k];
    const Aabb& box = boxes[i];
    entries_[k] = {box.lower[axis], box.upper[axis], box.lower[axis1], box.upper[axis1], box.lower[axis2], box.upper[axis2], i, active[i]};
  }
  auto before = [](const Entry& p, const Entry& q) { return p.lower < q.lower || (p.lower == q.lower && p.body < q.body); };
  int64_t moves = 0;
  const int64_t most_moves = 8 * int64_t(n);
  for (int k = 1; k < n && moves <= most_moves; ++k) {
    const Entry entry = entries_[k];
    int m = k;
    for (; m > 0 && before(entry, entries_[m - 1]); --m) entries_[m] = entries_[m - 1];
    entries_[m] = entry;
    moves += k - m;
  }
  if (moves > most_moves) std::sort(entries_.begin(), entries_.end(), before);
  for (int k = 0; k < n; ++k) order_[k] = entries_[k].body;
}

void BroadPhase::find_pairs(const std::vector<Aabb>& boxes, const std::vector<uint8_t>& active,
                            std::vector<BodyPair>& pairs, ThreadTeam* team) {
  pairs.clear();
  const int n = int(boxes.size());

  // The sweep axis: largest variance of the (finite) centres.
  Vec3 sum = Vec3::Zero(), sum_squares = Vec3::Zero();
  int finite = 0;
  for (const Aabb& box : boxes) {
    const Vec3 centre = (box.lower + box.upper) / 2;
    if (!is_finite(centre)) continue;
    sum += centre;
    sum_squares += centre.cwiseProduct(centre);
    ++finite;
  }
  int axis = 0;
  if (finite > 0) {
    const Vec3 variance = sum_squares / finite - (sum / finite).cwiseAbs2();
    variance.maxCoeff(&axis);
  }
  sort_entries(boxes, active, axis);

  // The sweep, shared when the team has threads and there are enough entries: a thread takes the
  // next run of entries as it finishes one (how much a run costs varies: a pyramid's wide bottom
  // rows have more neighbours than its top). Which thread finds which pair varies; the pairs do not.
  const int threads = team != nullptr && n >= kMinBodiesPerThread * 2 ? team->size() : 1;
  found_.resize(threads);
  for (Found& found : found_) found.pairs.clear();
  std::atomic<int> next_run{0};
  auto sweep = [&](int thread) {
    if (thread >= threads) return;
    std::vector<BodyPair>& found = found_[thread].pairs;
    for (int begin; (begin = next_run.fetch_add(kEntriesPerRun, std::memory_order_relaxed)) < n;) {
      for (int k = begin, end = std::min(begin + kEntriesPerRun, n); k < end; ++k) {
        const Entry& p = entries_[k];
        for (int m = k + 1; m < n && entries_[m].lower <= p.upper; ++m) {
          const Entry& q = entries_[m];
          // Without branches: which of the tests fails is unpredictable, and mispredictions cost
          // more than the comparisons.
          const bool hit = (p.active | q.active) & (p.lower1 <= q.upper1) & (q.lower1 <= p.upper1) &
                           (p.lower2 <= q.upper2) & (q.lower2 <= p.upper2);
          if (hit) found.push_back(p.body < q.body ? BodyPair{p.body, q.body} : BodyPair{q.body, p.body});
        }
      }
    }
  };
  if (threads > 1) team->run(sweep);
  else sweep(0);

  // Counting sort on a, then each (small) run of equal a sorted on b.
  starts_.assign(n + 1, 0);
  size_t count = 0;
  for (const Found& found : found_) {
    count += found.pairs.size();
    for (const BodyPair& pair : found.pairs) ++starts_[pair.a + 1];
  }
  for (int i = 0; i < n; ++i) starts_[i + 1] += starts_[i];
  pairs.resize(count);
  for (const Found& found : found_)
    for (const BodyPair& pair : found.pairs) pairs[starts_[pair.a]++] = pair;
  auto run = pairs.begin();
  for (int i = 0; i < n; ++i) {  // starts_[i] is now the end of run i
    const auto end = pairs.begin() + starts_[i];
    std::sort(run, end, [](const BodyPair& p, const BodyPair& q) { return p.b < q.b; });
    run = end;
  }
}

}  // namespace impulse::physics
