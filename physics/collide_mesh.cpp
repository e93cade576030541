// Narrow phase of a body against a static triangle mesh: each triangle near the body, as a sphere
// meets it (the nearest point) or as any other shape meets its slab (collide_convex.cpp), then
//   - where the nearest part of the triangle is a seam or corner that is not convex (mesh.h), the
//     body meets the triangle's plane instead, as it would a plane (collide.cpp's formulas): a
//     seam's own normal would snag a body sliding across a flat floor or rolling in a bowl (the
//     "ghost collision"), and the plane beyond a seam that folds inwards is where the body will
//     meet the triangle, so its speculative contact comes in time;
//   - the manifolds of triangles that share a normal (a floor's) are one, a point that two
//     triangles gave kept once, cut to four points.
// A contact's id is the one its pair gives it (manifold.h), whichever triangle it is on: the same
// point of the body keeps its id, and its warm start, as it rolls or slides onto the next triangle.
#include "physics/broadphase.h"
#include "physics/collide.h"
#include "physics/manifold.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

namespace {

// Normals this close are one (a flat floor's triangles, their normals computed apart), and points
// of one normal this close are one (two triangles' of the same corner).
constexpr Real kSameCos = 1 - Real(1e-9);
constexpr Real kSamePoint = Real(1e-4);  // m
constexpr Real kOnSegment = Real(1e-6);  // m
constexpr size_t kMostManifolds = 4;

// A's box, grown by the margin, in the mesh's frame.
void box_in_mesh(const Body& a, const Body& mesh, const Mat3& rotation, Real margin, Vec3& low, Vec3& high) {
  const Aabb box = body_aabb(a, margin);
  low = Vec3::Constant(INFINITY);
  high = -low;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner(k & 1 ? box.upper.x() : box.lower.x(), k & 2 ? box.upper.y() : box.lower.y(), k & 4 ? box.upper.z() : box.lower.z());
    const Vec3 local = rotation.transpose() * (corner - mesh.position);
    low = low.cwiseMin(local), high = high.cwiseMax(local);
  }
}

// Removes from `out` each point that lies on the segment between two others (within
// kOnSegment): where a triangle's side crosses a face or a line that touches two triangles, the
// crossing holds nothing that its ends do not, and as it moves along with the body it would shift
// the load between them, rocking a can that lies across a seam.
void drop_between(std::vector<Contact>& out) {
  for (size_t i = 0; i < out.size();) {
    bool between = false;
    for (size_t j = 0; j < out.size() && !between; ++j)
      for (size_t k = j + 1; k < out.size() && !between; ++k) {
        if (j == i || k == i) continue;
        const Vec3 d = out[k].point - out[j].point;
        const Real t = d.dot(out[i].point - out[j].point) / d.squaredNorm();
        between = t > 0 && t < 1 && (out[j].point + d * t - out[i].point).norm() < kOnSegment;
      }
    if (between)
      out.erase(out.begin() + long(i));
    else
      ++i;
  }
}

// Appends the contacts of `found` to `out`: those with one normal (within kSameCos) as one
// manifold with that normal exactly, its points between others dropped, cut to four points; of
// the manifolds, the kMostManifolds nearest (a body touches no more planes at once, a box in a
// corner of two walls and a floor; in a finely made bowl some tens of triangles come within the
// margin). Returns how many it appended.
int merge(const std::vector<Contact>& found, const Vec3& origin, std::vector<Contact>& out) {
  std::vector<std::vector<Contact>> manifolds;
  std::vector<bool> taken(found.size());
  for (size_t i = 0; i < found.size(); ++i) {
    if (taken[i]) continue;
    std::vector<Contact>& m = manifolds.emplace_back();
    const Vec3 normal = found[i].normal;
    for (size_t j = i; j < found.size(); ++j) {
      if (taken[j] || found[j].normal.dot(normal) < kSameCos) continue;
      taken[j] = true;
      Contact c = found[j];
      c.normal = normal;
      auto same = std::find_if(m.begin(), m.end(), [&](const Contact& kept) { return (kept.point - c.point).norm() < kSamePoint; });
      if (same == m.end())
        m.push_back(c);
      else if (c.separation < same->separation)
        *same = c;
    }
    drop_between(m);
    if (m.size() > 4) {  // a manifold keeps four
      Vec3 t1, t2;
      tangent_basis(normal, t1, t2);
      reduce_manifold(m, 0, normal, origin, search_direction(t1, t2));
    }
  }
  auto nearest = [](const std::vector<Contact>& m) {
    Real s = INFINITY;
    for (const Contact& c : m) s = std::min(s, c.separation);
    return s;
  };
  if (manifolds.size() > kMostManifolds) {
    std::stable_sort(manifolds.begin(), manifolds.end(), [&](const auto& x, const auto& y) { return nearest(x) < nearest(y); });
    manifolds.resize(kMostManifolds);
  }
  const size_t start = out.size();
  for (const std::vector<Contact>& m : manifolds) out.insert(out.end(), m.begin(), m.end());
  return int(out.size() - start);
}

}  // namespace

// A sphere (A) against the mesh (B), for each triangle within the margin whose front the centre is
// in front of: along the line to the nearest point on a convex seam or corner, else along the
// face's normal.
int collide_sphere_mesh(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Mesh& mesh = *b.shape.mesh();
  const Mat3 rotation = b.orientation.toRotationMatrix();
  Vec3 low, high;
  box_in_mesh(a, b, rotation, margin, low, high);
  const Vec3 centre = rotation.transpose() * (a.position - b.position);
  const Real radius = a.shape.radius;
  std::vector<Contact> found;
  mesh.query(low, high, [&](int t) {
    const MeshTriangle& tri = mesh.triangles[t];
    const Vec3 &p0 = mesh.vertices[tri.corners[0]], &p1 = mesh.vertices[tri.corners[1]], &p2 = mesh.vertices[tri.corners[2]];
    const Real height = tri.normal.dot(centre - p0);
    if (height < 0) return;  // behind its front
    Vec3 nearest;
    const int part = nearest_on_triangle(centre, p0, p1, p2, nearest);
    const Real apart = (centre - nearest).norm();
    if (apart - radius > margin) return;
    Vec3 n = tri.normal;
    Real distance = height;
    if (part != 0 && touches_own_normal(tri, part)) {
      distance = apart;
      if (distance > Real(1e-12)) n = (centre - nearest) / distance;
    }
    const Real separation = distance - radius;
    if (separation > margin) return;
    const Vec3 normal = rotation * n;
    const Vec3 on_mesh = b.position + rotation * (centre - n * distance);
    found.push_back({ia, ib, (on_mesh + a.position - normal * radius) / 2, normal, separation, uint32_t(part)});
  });
  if (found.size() > kMostManifolds) {  // each point its own plane: the nearest, before merging
    std::partial_sort(found.begin(), found.begin() + kMostManifolds, found.end(),
                      [](const Contact& x, const Contact& y) { return x.separation < y.separation; });
    found.resize(kMostManifolds);
  }
  return merge(found, a.position, out);
}

// Another shape (A) against the mesh (B): each triangle's slab through collide_convex; where its
// normal is not the face's and the seam or corner nearest the deepest point is not convex, A
// against the triangle's plane.
int collide_convex_mesh(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Mesh& mesh = *b.shape.mesh();
  const Mat3 rotation = b.orientation.toRotationMatrix();
  Vec3 low, high;
  box_in_mesh(a, b, rotation, margin, low, high);
  std::vector<Contact> found;
  Body slab;
  slab.orientation = b.orientation;
  mesh.query(low, high, [&](int t) {
    const MeshTriangle& tri = mesh.triangles[t];
    const Vec3 face = rotation * tri.normal;
    if (face.dot(a.position - b.position) - face.dot(rotation * mesh.vertices[tri.corners[0]]) < 0) return;  // A's centre behind its front
    slab.shape = Shape::convex(std::shared_ptr<const Hull>(b.shape.data, &mesh.slabs[t]));
    slab.position = b.position + rotation * mesh.slab_centres[t];
    const size_t first = found.size();
    const int count = collide_convex(a, ia, slab, ib, margin, found);
    if (count > 0 && found[first].normal.dot(face) < kSameCos) {  // not the face's: a side's, an edge's, EPA's
      size_t deepest = first;
      for (size_t i = first; i < found.size(); ++i)
        if (found[i].separation < found[deepest].separation) deepest = i;
      const Vec3 x = rotation.transpose() * (found[deepest].point - b.position);
      Vec3 nearest;
      const int part = nearest_on_triangle(x, mesh.vertices[tri.corners[0]], mesh.vertices[tri.corners[1]], mesh.vertices[tri.corners[2]], nearest);
      if (part == 0 || !touches_own_normal(tri, part)) {
        found.resize(first);
        Body plane;
        plane.shape = Shape::plane(face, face.dot(b.position + rotation * mesh.vertices[tri.corners[0]]));
        collide(a, ia, plane, ib, margin, found);
      }
    }
  });
  return merge(found, a.position, out);
}

}  // namespace impulse::physics
