// A static triangle mesh: the surface of a "mesh" shape (a floor, a bowl, a half-pipe), in its
// body's frame. One-sided: each triangle's front is where its corners turn counter-clockwise.
#pragma once
#include "physics/hull.h"
#include "physics/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace impulse::physics {

struct MeshTriangle {
  std::array<int, 3> corners;  // into Mesh::vertices, counter-clockwise seen from the front
  Vec3 normal = Vec3::UnitY(); // the front's, unit
  // Bit k set where edge k (corners k to k + 1) is convex: a body may touch it along a normal of
  // its own. A seam between two triangles that meet flat, or fold towards their fronts (a valley),
  // is not: whatever touches there touches a face, and a normal of the seam's would snag a body
  // sliding across it (the "ghost collision"). Edges of one triangle only (the rim) are convex.
  uint8_t convex_edges = 7;
};

// A bounding-box tree over the triangles: node k's box holds its triangles, Mesh::order[first,
// first + count) for a leaf (count > 0); an inner node's children are k + 1 and `second`.
struct MeshNode {
  Vec3 low, high;
  int first = 0, count = 0, second = 0;
};

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  // Each triangle as a thin prism behind its front (its corners about its own centre `slab_centres`),
  // for the pairs found by GJK and clipping (collide_convex.cpp).
  std::vector<Hull> slabs;
  std::vector<Vec3> slab_centres;
  std::vector<MeshNode> nodes;
  std::vector<int> order;

  // Calls visit(t) for each triangle whose box meets [low, high] (this frame).
  template <class Visit>
  void query(const Vec3& low, const Vec3& high, Visit&& visit) const {
    if (nodes.empty()) return;
    int stack[64], size = 0;
    stack[size++] = 0;
    while (size > 0) {
      const MeshNode& node = nodes[stack[--size]];
      if ((node.low.array() > high.array()).any() || (node.high.array() < low.array()).any()) continue;
      if (node.count > 0) {
        for (int i = node.first; i < node.first + node.count; ++i) visit(order[i]);
      } else if (size + 2 <= 64) {
        stack[size++] = node.second;
        stack[size++] = int(&node - nodes.data()) + 1;
      }
    }
  }
};

// The mesh of `vertices` and `triangles` (indices, counter-clockwise from the front): normals,
// convex edges, slabs, tree. Throws std::invalid_argument, the reason in words, for no triangles,
// an index out of range, a non-finite vertex, or a triangle without area.
Mesh make_mesh(std::span<const Vec3> vertices, std::span<const std::array<int, 3>> triangles);

// Which part of triangle (p0, p1, p2) is nearest x: 0 its inside, 1 + k edge k (corners k to k + 1),
// 4 + k corner k; `nearest` the point (Ericson, "Real-Time Collision Detection", 5.1.5).
int nearest_on_triangle(const Vec3& x, const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec3& nearest);

// Whether that part of `triangle` can give a normal of its own: its inside, or a convex edge, or a
// corner with a convex edge.
bool touches_own_normal(const MeshTriangle& triangle, int part);

}  // namespace impulse::physics
