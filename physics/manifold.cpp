// Cutting a pair's contact points down to the four that hold it best.
#include "physics/manifold.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace impulse::physics {

namespace {

// A later candidate must beat the best so far by this factor (Box3D's pecking order).
constexpr Real kBias = 0.95;

}  // namespace

int reduce_manifold(std::vector<Contact>& out, size_t first, const Vec3& normal, const Vec3& origin, const Vec3& search) {
  Contact* points = out.data() + first;
  const int count = int(out.size() - first);
  if (count <= 4) return count;
  std::array<int, 4> keep{-1, -1, -1, -1};
  int kept = 0;
  auto taken = [&](int i) { return std::find(keep.begin(), keep.begin() + kept, i) != keep.begin() + kept; };

  // 1. The point farthest along `search`, a direction fixed in one of the bodies (Box3D's way):
  // the points keep their ranking while the bodies rock. Depth counts too, but little: ranked by
  // depth first, the choice flips between points of nearly equal depth as a box rocks, and each
  // flip hands the load to another set of four, which rocks it on (the heaps that would not rest).
  int best = 0;
  Real best_score = -INFINITY;
  for (int i = 0; i < count; ++i) {
    const Real score = search.dot(points[i].point - origin) - points[i].separation;
    if (kBias * score > best_score) best = i, best_score = score;
  }
  keep[kept++] = best;
  const Vec3 a = points[best].point;

  // 2. The farthest from it, measured in the contact plane.
  best = -1;
  best_score = 0;
  for (int i = 0; i < count; ++i) {
    if (taken(i)) continue;
    Vec3 d = points[i].point - a;
    d -= d.dot(normal) * normal;
    const Real score = d.squaredNorm();
    if (kBias * score > best_score) best = i, best_score = score;
  }
  if (best < 0) {
    out[first] = points[keep[0]];
    out.resize(first + 1);
    return 1;
  }
  keep[kept++] = best;
  const Vec3 b = points[best].point;

  // 3. The largest triangle with those two.
  best = -1;
  best_score = 0;
  Real signed_area = 0;
  for (int i = 0; i < count; ++i) {
    if (taken(i)) continue;
    const Real area = normal.dot((b - a).cross(points[i].point - a));
    if (kBias * std::abs(area) > best_score) best = i, best_score = std::abs(area), signed_area = area;
  }
  if (best >= 0) {
    keep[kept++] = best;
    const Vec3 c = points[best].point;
    // 4. The point that adds the most area outside that triangle.
    const Real sign = signed_area < 0 ? -1 : 1;
    best = -1;
    best_score = 0;
    for (int i = 0; i < count; ++i) {
      if (taken(i)) continue;
      const Vec3& p = points[i].point;
      // Positive beyond an edge of the triangle, whichever way round it winds.
      const Real outside = std::max({sign * normal.dot((p - a).cross(b - a)), sign * normal.dot((p - b).cross(c - b)),
                                     sign * normal.dot((p - c).cross(a - c))});
      if (kBias * outside > best_score) best = i, best_score = outside;
    }
    if (best >= 0) keep[kept++] = best;
  }

  // Keep the survivors in their original order (the clip order), for a stable solve order.
  // (Ascending, so each moves down onto a slot it no longer needs.)
  for (int k = 1; k < kept; ++k)
    for (int m = k; m > 0 && keep[m - 1] > keep[m]; --m) std::swap(keep[m - 1], keep[m]);
  for (int k = 0; k < kept; ++k) points[k] = points[keep[k]];
  out.resize(first + kept);
  return kept;
}

}  // namespace impulse::physics
