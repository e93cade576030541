// Narrow phase of a convex hull against a sphere and against a plane (the other pairs:
// collide_convex.cpp).
#include "physics/collide.h"
#include "physics/manifold.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse::physics {

namespace {

// The point of segment p-q nearest x.
Vec3 nearest_on_segment(const Vec3& p, const Vec3& q, const Vec3& x) {
  const Vec3 d = q - p;
  const Real t = d.squaredNorm() > 0 ? std::clamp(d.dot(x - p) / d.squaredNorm(), Real(0), Real(1)) : Real(0);
  return p + d * t;
}

}  // namespace

// A sphere (A) against a hull (B), in the hull's frame: outside, the nearest point of the faces the
// centre is in front of (on a face where the centre's shadow falls inside it, else on its sides);
// inside, out through the face nearest the centre.
int collide_sphere_hull(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Hull& hull = *b.shape.hull();
  const Mat3 rotation = b.orientation.toRotationMatrix();
  const Vec3 centre = rotation.transpose() * (a.position - b.position);
  const Real radius = a.shape.radius;
  int nearest_face = 0;
  Real highest = -std::numeric_limits<Real>::infinity();
  for (int f = 0; f < int(hull.faces.size()); ++f) {
    const Real height = hull.faces[f].normal.dot(centre) - hull.faces[f].offset;
    if (height > highest) highest = height, nearest_face = f;
  }
  if (highest - radius > margin) return 0;
  Vec3 normal, on_hull = centre;
  Real separation;
  if (highest <= 0) {
    normal = hull.faces[nearest_face].normal;
    on_hull = centre - normal * highest;
    separation = highest - radius;
  } else {
    Real closest = std::numeric_limits<Real>::infinity();
    for (const HullFace& face : hull.faces) {
      const Real height = face.normal.dot(centre) - face.offset;
      if (height <= 0) continue;
      const Vec3 shadow = centre - face.normal * height;
      bool inside = true;
      for (int k = 0; k < face.count && inside; ++k) {
        const Vec3& p = hull.corners[hull.corner_of(face, k)];
        const Vec3& q = hull.corners[hull.corner_of(face, (k + 1) % face.count)];
        inside = (q - p).cross(shadow - p).dot(face.normal) >= 0;
      }
      if (inside) {
        if (height < closest) closest = height, on_hull = shadow;
        continue;
      }
      for (int k = 0; k < face.count; ++k) {
        const Vec3 x = nearest_on_segment(hull.corners[hull.corner_of(face, k)], hull.corners[hull.corner_of(face, (k + 1) % face.count)], centre);
        const Real distance = (centre - x).norm();
        if (distance < closest) closest = distance, on_hull = x;
      }
    }
    separation = closest - radius;
    if (separation > margin) return 0;
    normal = (centre - on_hull) / closest;
  }
  const Vec3 world_normal = rotation * normal;
  const Vec3 on_sphere = a.position - world_normal * radius;
  out.push_back({ia, ib, (b.position + rotation * on_hull + on_sphere) / 2, world_normal, separation, feature::corner(0)});
  return 1;
}

// A hull (A) against a plane (B): the face that looks most against the plane (as a box's,
// collide_box.cpp), by its corners or, where it has more than four, its quad (hull.h), below the
// plane plus the margin; and the lowest corner where it is deeper than those by more than kDeeper
// (a face tipped onto the plane).
int collide_hull_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  constexpr Real kDeeper = 0.0005;  // m
  const Hull& hull = *a.shape.hull();
  const Mat3 rotation = a.orientation.toRotationMatrix();
  const Vec3& n = b.shape.normal;
  const Vec3 down = rotation.transpose() * -n;
  int lowest = 0, facing = 0;
  for (int i = 1; i < int(hull.corners.size()); ++i)
    if (hull.corners[i].dot(down) > hull.corners[lowest].dot(down)) lowest = i;
  const Real height = n.dot(a.position) - b.shape.offset - hull.corners[lowest].dot(down);  // the lowest corner's separation
  if (height > margin) return 0;
  for (int f = 1; f < int(hull.faces.size()); ++f)
    if (hull.faces[f].normal.dot(down) > hull.faces[facing].normal.dot(down)) facing = f;

  const size_t first = out.size();
  Real deepest = INFINITY;
  auto add = [&](const Vec3& local, uint32_t id) {
    const Vec3 point = a.position + rotation * local;
    const Real separation = n.dot(point) - b.shape.offset;
    deepest = std::min(deepest, separation);
    if (separation <= margin) out.push_back({ia, ib, point - n * (separation / 2), n, separation, id});
  };
  const HullFace& face = hull.faces[facing];
  bool lowest_added = false;
  if (face.count > 4) {
    for (int q = 0; q < 4; ++q) add(face.quad[q], feature::corner(int(hull.corners.size()) + q));
  } else {
    for (int k = 0; k < face.count; ++k) {
      add(hull.corners[hull.corner_of(face, k)], feature::corner(hull.corner_of(face, k)));
      lowest_added = lowest_added || hull.corner_of(face, k) == lowest;
    }
  }
  if (!lowest_added && height < deepest - kDeeper) add(hull.corners[lowest], feature::corner(lowest));
  Vec3 t1, t2;
  tangent_basis(n, t1, t2);
  return reduce_manifold(out, first, n, a.position, search_direction(t1, t2));
}

}  // namespace impulse::physics
