// Sweep and prune on the axis of largest variance, with the pairs put in (i, j) order.
#include "physics/broadphase.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse::physics {

Aabb body_aabb(const Body& body, Real margin) {
  if (body.shape.type == ShapeType::plane) {
    const Real inf = std::numeric_limits<Real>::infinity();
    return {Vec3::Constant(-inf), Vec3::Constant(inf)};
  }
  const Vec3 reach = (body.shape.type == ShapeType::box
                          ? Vec3(body.orientation.toRotationMatrix().cwiseAbs() * body.shape.half_extents)
                          : Vec3::Constant(body.shape.radius)) +
                     Vec3::Constant(margin);
  return {body.position - reach, body.position + reach};
}

void BroadPhase::find_pairs(const std::vector<Aabb>& boxes, const std::vector<uint8_t>& active,
                            std::vector<BodyPair>& pairs) {
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
  const int axis1 = (axis + 1) % 3, axis2 = (axis + 2) % 3;

  entries_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Aabb& box = boxes[i];
    entries_[i] = {box.lower[axis], box.upper[axis], box.lower[axis1], box.upper[axis1],
                   box.lower[axis2], box.upper[axis2], i, active[i]};
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& p, const Entry& q) {
    return p.lower < q.lower || (p.lower == q.lower && p.body < q.body);
  });

  unsorted_.clear();
  for (int k = 0; k < n; ++k) {
    const Entry& p = entries_[k];
    for (int m = k + 1; m < n && entries_[m].lower <= p.upper; ++m) {
      const Entry& q = entries_[m];
      // Without branches: which of the tests fails is unpredictable, and mispredictions cost more
      // than the comparisons.
      const bool hit = (p.active | q.active) & (p.lower1 <= q.upper1) & (q.lower1 <= p.upper1) &
                       (p.lower2 <= q.upper2) & (q.lower2 <= p.upper2);
      if (hit) unsorted_.push_back(p.body < q.body ? BodyPair{p.body, q.body} : BodyPair{q.body, p.body});
    }
  }

  // Counting sort on a, then each (small) run of equal a sorted on b.
  starts_.assign(n + 1, 0);
  for (const BodyPair& pair : unsorted_) ++starts_[pair.a + 1];
  for (int i = 0; i < n; ++i) starts_[i + 1] += starts_[i];
  pairs.resize(unsorted_.size());
  for (const BodyPair& pair : unsorted_) pairs[starts_[pair.a]++] = pair;
  auto run = pairs.begin();
  for (int i = 0; i < n; ++i) {  // starts_[i] is now the end of run i
    const auto end = pairs.begin() + starts_[i];
    std::sort(run, end, [](const BodyPair& p, const BodyPair& q) { return p.b < q.b; });
    run = end;
  }
}

}  // namespace impulse::physics
