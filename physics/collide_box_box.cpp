// Narrow phase of two boxes: separating axes, then a clipped face manifold or an edge pair.
#include "physics/collide.h"
#include "physics/manifold.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace impulse::physics {

namespace {

// Edge pairs nearer to parallel than this sine are left to the face axes.
constexpr Real kParallelSine = 1e-3;
// An axis displaces a preferred one (A's faces, then B's faces, then edge pairs) only when its
// separation is larger by this much: the face manifold is steadier and has more points.
constexpr Real kRelativeTolerance = 0.05;
constexpr Real kAbsoluteTolerance = 0.0005;  // m
// Incident points this close outside a reference side plane are kept rather than clipped, so
// that flush stacks keep their corner ids (m, capped at 1 % of the reference face): a point
// may lie this far beyond the reference face's rim.
constexpr Real kClipTolerance = 0.0005;
// A cached reference face is used again while its deepest point moved less than this (m; Box3D's
// linear slop).
constexpr Real kCacheSlop = 0.005;

bool clearly_greater(Real candidate, Real current) {
  return candidate > current + kRelativeTolerance * std::abs(current) + kAbsoluteTolerance;
}

struct BoxFrame {
  Vec3 centre;
  Mat3 axes;  // columns: the box's x, y, z in world space
  Vec3 half;
  Vec3 corner(int index) const { return centre + axes * box_corner(half, index); }
};

int face_index(int axis, Real sign) { return 2 * axis + (sign > 0 ? 0 : 1); }

// The edge along `axis` through `corner` (manifold.h's numbering).
int edge_index(int axis, int corner) {
  const int low = axis == 0 ? 1 : 0, high = axis == 2 ? 1 : 2;
  return 4 * axis + ((corner >> low) & 1) + 2 * ((corner >> high) & 1);
}

// A vertex of the incident polygon while it is clipped: its id (feature::face_point's point)
// and the id of the polygon edge that leaves it (0-11 a box edge, 12-15 along side plane 0-3).
struct ClipVertex {
  Vec3 p;
  int id;
  int edge;
};
using Polygon = std::array<ClipVertex, 8>;  // a quad clipped by four planes has at most 8 sides

// Sutherland-Hodgman: keeps the part of `in` where dot(m, p) <= offset. A vertex up to
// `tolerance` outside stays as it is (no new points right next to it); cuts are exact.
int clip(const Polygon& in, int count, const Vec3& m, Real offset, Real tolerance, int side, Polygon& out) {
  int n = 0;
  for (int i = 0; i < count; ++i) {
    const ClipVertex& cur = in[i];
    const ClipVertex& next = in[(i + 1) % count];
    const Real dc = m.dot(cur.p) - offset, dn = m.dot(next.p) - offset;
    auto cut = [&](int edge_after) {
      const Real t = dc / (dc - dn);
      return ClipVertex{cur.p + t * (next.p - cur.p), int(feature::clip_point(cur.edge, side)), edge_after};
    };
    if (dc <= tolerance) {
      if (dn <= tolerance) {
        out[n++] = cur;
      } else if (dc < 0) {
        out[n++] = cur;
        out[n++] = cut(12 + side);  // leaving: the polygon now runs along the side plane
      } else {
        out[n++] = {cur.p, cur.id, 12 + side};
      }
    } else if (dn < 0) {
      out[n++] = cut(cur.edge);  // entering
    }
  }
  return n;
}

// Face contact: the face of `ref` along `axis` (outward normal n pointing at `inc`) against the
// most opposed face of `inc`, clipped to the reference face's sides. Appends the points within
// `margin` (normal -n when ref is A, as A is pushed away from B), reduced to four. `deepest` is
// the separation of the deepest clipped point, kept or not.
int face_contact(const BoxFrame& ref, const BoxFrame& inc, int axis, Real sign, bool ref_is_b, int ia, int ib,
                 Real margin, std::vector<Contact>& out, Real& deepest) {
  const Vec3 n = sign * ref.axes.col(axis);

  // Incident face: the face of `inc` whose outward normal is most against n.
  const Vec3 dots = inc.axes.transpose() * n;
  int inc_axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(dots[k]) > std::abs(dots[inc_axis])) inc_axis = k;
  const int u = (inc_axis + 1) % 3, v = (inc_axis + 2) % 3;
  const int base = dots[inc_axis] > 0 ? 0 : 1 << inc_axis;
  const std::array<int, 4> corners{base, base | 1 << u, base | 1 << u | 1 << v, base | 1 << v};
  Polygon buffers[2];
  Polygon* polygon = &buffers[0];
  Polygon* scratch = &buffers[1];
  for (int k = 0; k < 4; ++k) {
    const int along = k % 2 == 0 ? u : v;  // corners k and k+1 differ along this axis
    (*polygon)[k] = {inc.corner(corners[k]), corners[k], edge_index(along, corners[k])};
  }
  int count = 4;

  const int su = (axis + 1) % 3, sv = (axis + 2) % 3;
  const std::array<int, 4> side_axis{su, su, sv, sv};
  for (int side = 0; side < 4 && count > 0; ++side) {
    const Real side_sign = side % 2 == 0 ? 1 : -1;
    const Vec3 m = side_sign * ref.axes.col(side_axis[side]);
    const Real half = ref.half[side_axis[side]];
    count = clip(*polygon, count, m, m.dot(ref.centre) + half, std::min(kClipTolerance, half / 100), side, *scratch);
    std::swap(polygon, scratch);
  }

  const Vec3 normal = ref_is_b ? n : Vec3(-n);
  const int face = face_index(axis, sign);
  const Real face_offset = n.dot(ref.centre) + ref.half[axis];
  const size_t first = out.size();
  deepest = INFINITY;
  for (int k = 0; k < count; ++k) {
    const ClipVertex& vertex = (*polygon)[k];
    const Real separation = n.dot(vertex.p) - face_offset;
    deepest = std::min(deepest, separation);
    if (separation > margin) continue;
    out.push_back({ia, ib, vertex.p - n * (separation / 2), normal, separation,
                   feature::face_point(ref_is_b ? 1 : 0, face, vertex.id)});
  }
  return reduce_manifold(out, first, normal, ref.centre, search_direction(ref.axes.col(su), ref.axes.col(sv)));
}

// Closest points of segments p1 + s d1 and p2 + t d2, s and t in [0, 1] (Ericson, 5.1.9).
void closest_points(const Vec3& p1, const Vec3& d1, const Vec3& p2, const Vec3& d2, Vec3& c1, Vec3& c2) {
  const Vec3 r = p1 - p2;
  const Real a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
  const Real denom = a * e - b * b;  // > 0: the edges are not parallel here
  Real s = denom > 0 ? std::clamp((b * f - c * e) / denom, Real(0), Real(1)) : 0;
  Real t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, Real(0), Real(1));
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, Real(0), Real(1));
  }
  c1 = p1 + s * d1;
  c2 = p2 + t * d2;
}

// Edge contact: A's edge along axis i against B's along axis j, the edges that reach farthest
// along n (from A to B) and -n. One point midway between their closest points.
int edge_contact(const BoxFrame& a, const BoxFrame& b, int i, int j, const Vec3& n, int ia, int ib, Real margin,
                 std::vector<Contact>& out) {
  int corner_a = 0, corner_b = 0;
  for (int k = 0; k < 3; ++k) {
    if (k != i && n.dot(a.axes.col(k)) > 0) corner_a |= 1 << k;
    if (k != j && n.dot(b.axes.col(k)) < 0) corner_b |= 1 << k;
  }
  const Vec3 pa = a.corner(corner_a), pb = b.corner(corner_b);
  Vec3 ca, cb;
  closest_points(pa, a.corner(corner_a | 1 << i) - pa, pb, b.corner(corner_b | 1 << j) - pb, ca, cb);
  const Real separation = n.dot(cb - ca);
  if (separation > margin) return 0;
  out.push_back({ia, ib, (ca + cb) / 2, -n, separation,
                 feature::edge_pair(edge_index(i, corner_a), edge_index(j, corner_b))});
  return 1;
}

}  // namespace

// Two boxes: the separating axis test over the 15 axes (3 + 3 face normals, 9 edge cross
// products). Any axis (or world axis) separating by more than the margin means no contact;
// otherwise the axis of least penetration, faces preferred, makes the manifold: a reference face
// with the other box's face clipped to it, or one point between two crossing edges. Last step's
// reference face (`cache`) comes first while it gives points as deep as before, within a slop.
int collide_boxes(const Body& body_a, int ia, const Body& body_b, int ib, Real margin, std::vector<Contact>& out,
                  SatCache* cache) {
  const BoxFrame a{body_a.position, body_a.orientation.toRotationMatrix(), body_a.shape.half_extents};
  const BoxFrame b{body_b.position, body_b.orientation.toRotationMatrix(), body_b.shape.half_extents};
  const Vec3 d = b.centre - a.centre;
  // The world axes first: cheap, and where they separate the boxes farther than the other axes
  // do, they keep a speculative contact from starting too early (and agree with the broad phase).
  const Vec3 reach = a.axes.cwiseAbs() * a.half + b.axes.cwiseAbs() * b.half;
  if ((d.cwiseAbs() - reach).maxCoeff() > margin) return 0;

  const Mat3 c = a.axes.transpose() * b.axes;  // c(i, j) = A's axis i . B's axis j
  const Mat3 abs_c = c.cwiseAbs();
  const Vec3 da = a.axes.transpose() * d;  // in A's frame
  const Vec3 db = b.axes.transpose() * d;  // in B's frame
  auto sign_a = [&](int k) { return da[k] > 0 ? 1 : -1; };  // A's face towards B along axis k
  auto sign_b = [&](int k) { return db[k] > 0 ? -1 : 1; };  // B's face towards A
  Real deepest = 0;

  // Last step's reference face, while it still holds (SatCache).
  if (cache && cache->reference >= 0) {
    const bool ref_is_b = cache->reference == 1;
    const int axis = cache->axis;
    if (cache->sign == (ref_is_b ? sign_b(axis) : sign_a(axis))) {
      const size_t first = out.size();
      const int added = face_contact(ref_is_b ? b : a, ref_is_b ? a : b, axis, cache->sign, ref_is_b, ia, ib, margin, out, deepest);
      if (added > 0 && std::abs(deepest - cache->deepest) < kCacheSlop) {
        cache->deepest = float(deepest);
        return added;
      }
      out.resize(first);
    }
  }
  if (cache) cache->reference = -1;

  int face_a = 0, face_b = 0;
  Real sep_a = -INFINITY, sep_b = -INFINITY;
  for (int k = 0; k < 3; ++k) {
    const Real s_a = std::abs(da[k]) - (a.half[k] + abs_c.row(k).dot(b.half));
    if (s_a > sep_a) sep_a = s_a, face_a = k;
    const Real s_b = std::abs(db[k]) - (abs_c.col(k).dot(a.half) + b.half[k]);
    if (s_b > sep_b) sep_b = s_b, face_b = k;
  }
  if (std::max(sep_a, sep_b) > margin) return 0;

  int edge_i = -1, edge_j = -1;
  Real sep_edge = -INFINITY;
  Vec3 edge_axis = Vec3::Zero();  // in A's frame, unit, not yet oriented
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 axis = Vec3::Unit(i).cross(c.col(j));  // A's axis i x B's axis j, in A's frame
      const Real length = axis.norm();
      if (length < kParallelSine) continue;
      const Real reach_a = axis.cwiseAbs().dot(a.half);
      const Real reach_b = (c.transpose() * axis).cwiseAbs().dot(b.half);
      const Real s = (std::abs(da.dot(axis)) - reach_a - reach_b) / length;
      if (s > margin) return 0;
      if (s > sep_edge) sep_edge = s, edge_i = i, edge_j = j, edge_axis = axis / length;
    }
  }

  const bool use_b = clearly_greater(sep_b, sep_a);
  const Real sep_face = use_b ? sep_b : sep_a;
  const bool use_edge = edge_i >= 0 && clearly_greater(sep_edge, sep_face);
  Vec3 n_edge = a.axes * edge_axis;
  if (n_edge.dot(d) < 0) n_edge = -n_edge;  // from A to B

  if (!use_edge) {
    const int axis = use_b ? face_b : face_a;
    const int sign = use_b ? sign_b(face_b) : sign_a(face_a);
    const int added = face_contact(use_b ? b : a, use_b ? a : b, axis, sign, use_b, ia, ib, margin, out, deepest);
    if (added > 0 && cache) *cache = {int8_t(use_b ? 1 : 0), int8_t(axis), int8_t(sign), float(deepest)};
    if (added > 0 || edge_i < 0) return added;
  }
  return edge_contact(a, b, edge_i, edge_j, n_edge, ia, ib, margin, out);
}

}  // namespace impulse::physics
