#include "physics/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

namespace impulse::physics {

namespace {

// Two triangles whose normals differ by less than this meet flat: their seam gives no normal of
// its own (Jolt's active edges use the same 5 degrees).
constexpr Real kFlatCos = 0.99619;  // cos 5 degrees
constexpr int kLeafTriangles = 4;

std::string show(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "[%g, %g, %g]", p.x(), p.y(), p.z());
  return text;
}

// The prism between the triangle and its copy `depth` behind it, about its own centre.
Hull slab(const Vec3 (&p)[3], const Vec3& normal, Real depth, Vec3& centre) {
  centre = (p[0] + p[1] + p[2]) / 3 - normal * (depth / 2);
  Hull h;
  for (int k = 0; k < 3; ++k) h.corners.push_back(p[k] - centre);
  for (int k = 0; k < 3; ++k) h.corners.push_back(p[k] - normal * depth - centre);
  auto face = [&](const Vec3& n, std::initializer_list<int> corners) {
    HullFace f;
    f.normal = n;
    f.first = int(h.face_corners.size());
    f.count = int(corners.size());
    h.face_corners.insert(h.face_corners.end(), corners);
    f.offset = n.dot(h.corners[*corners.begin()]);
    h.faces.push_back(f);
  };
  face(normal, {0, 1, 2});
  face(-normal, {5, 4, 3});
  for (int k = 0; k < 3; ++k) {  // edge k's side, outward: along the edge x the normal
    const int next = (k + 1) % 3;
    face((p[next] - p[k]).cross(normal).normalized(), {k, k + 3, next + 3, next});
  }
  return h;
}

int build_tree(Mesh& mesh, const std::vector<Vec3>& low, const std::vector<Vec3>& high, const std::vector<Vec3>& mid, int first,
               int count) {
  const int index = int(mesh.nodes.size());
  mesh.nodes.emplace_back();
  MeshNode node;
  node.low = Vec3::Constant(INFINITY);
  node.high = Vec3::Constant(-INFINITY);
  for (int i = first; i < first + count; ++i) {
    node.low = node.low.cwiseMin(low[mesh.order[i]]);
    node.high = node.high.cwiseMax(high[mesh.order[i]]);
  }
  if (count <= kLeafTriangles) {
    node.first = first;
    node.count = count;
  } else {  // halves by the centres along the longest side
    int axis = 0;
    (node.high - node.low).maxCoeff(&axis);
    int* begin = mesh.order.data() + first;
    std::nth_element(begin, begin + count / 2, begin + count, [&](int x, int y) { return mid[x][axis] < mid[y][axis]; });
    build_tree(mesh, low, high, mid, first, count / 2);
    node.second = build_tree(mesh, low, high, mid, first + count / 2, count - count / 2);
  }
  mesh.nodes[index] = node;
  return index;
}

}  // namespace

Mesh make_mesh(std::span<const Vec3> vertices, std::span<const std::array<int, 3>> triangles) {
  if (triangles.empty()) throw std::invalid_argument("a mesh needs at least one triangle");
  Mesh mesh;
  // The same place named twice (a file's corners split by their texture or normal) is one corner.
  std::map<std::array<Real, 3>, int> welded;
  std::vector<int> weld(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec3& v = vertices[i];
    if (!is_finite(v)) throw std::invalid_argument("a mesh's vertices must be finite numbers, got " + show(v));
    auto [at, added] = welded.try_emplace({v.x(), v.y(), v.z()}, int(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(v);
    weld[i] = at->second;
  }
  for (size_t t = 0; t < triangles.size(); ++t) {
    MeshTriangle tri;
    for (int k = 0; k < 3; ++k) {
      const int i = triangles[t][k];
      if (i < 0 || size_t(i) >= vertices.size())
        throw std::invalid_argument("triangle " + std::to_string(t + 1) + " names vertex " + std::to_string(i + 1) + " of " +
                                    std::to_string(vertices.size()));
      tri.corners[k] = weld[i];
    }
    const Vec3 &p0 = mesh.vertices[tri.corners[0]], &p1 = mesh.vertices[tri.corners[1]], &p2 = mesh.vertices[tri.corners[2]];
    const Vec3 n = (p1 - p0).cross(p2 - p0);
    const Real longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
    if (!(n.norm() > Real(1e-9) * longest * longest))
      throw std::invalid_argument("triangle " + std::to_string(t + 1) + " has no area: its corners " + show(p0) + ", " + show(p1) +
                                  " and " + show(p2) + " are on one line");
    tri.normal = n.normalized();
    mesh.triangles.push_back(tri);
  }
  // Convex edges: a seam is convex where the other triangle's far corner is behind this one's
  // front and their normals differ by more than kFlatCos.
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;  // (low, high corner) -> (triangle, edge)
  for (int t = 0; t < int(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.triangles[t].corners[k], j = mesh.triangles[t].corners[(k + 1) % 3];
      edges[{std::min(i, j), std::max(i, j)}].push_back({t, k});
    }
  for (const auto& [ends, sides] : edges) {
    if (sides.size() != 2) continue;  // a rim, or more than two faces on one edge: convex
    for (int s = 0; s < 2; ++s) {
      MeshTriangle& tri = mesh.triangles[sides[s].first];
      const MeshTriangle& other = mesh.triangles[sides[1 - s].first];
      const Vec3& far = mesh.vertices[other.corners[(sides[1 - s].second + 2) % 3]];
      const Real behind = tri.normal.dot(far - mesh.vertices[ends.first]);
      const bool convex = behind < 0 && tri.normal.dot(other.normal) < kFlatCos;
      if (!convex) tri.convex_edges &= uint8_t(~(1u << sides[s].second));
    }
  }
  // Slabs as deep as half the triangle's longest side, and the tree over them.
  const size_t n = mesh.triangles.size();
  std::vector<Vec3> low(n), high(n), mid(n);
  for (size_t t = 0; t < n; ++t) {
    const MeshTriangle& tri = mesh.triangles[t];
    const Vec3 p[3] = {mesh.vertices[tri.corners[0]], mesh.vertices[tri.corners[1]], mesh.vertices[tri.corners[2]]};
    const Real longest = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
    Vec3 centre;
    mesh.slabs.push_back(slab(p, tri.normal, longest / 2, centre));
    mesh.slab_centres.push_back(centre);
    low[t] = high[t] = centre;
    for (const Vec3& c : mesh.slabs.back().corners) low[t] = low[t].cwiseMin(centre + c), high[t] = high[t].cwiseMax(centre + c);
    mid[t] = (p[0] + p[1] + p[2]) / 3;
  }
  mesh.order.resize(n);
  std::iota(mesh.order.begin(), mesh.order.end(), 0);
  build_tree(mesh, low, high, mid, 0, int(n));
  return mesh;
}

int nearest_on_triangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& nearest) {
  const Vec3 ab = b - a, ac = c - a, ap = x - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return nearest = a, 4;
  const Vec3 bp = x - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return nearest = b, 5;
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return nearest = a + ab * (d1 / (d1 - d3)), 1;
  const Vec3 cp = x - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return nearest = c, 6;
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return nearest = a + ac * (d2 / (d2 - d6)), 3;
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return nearest = b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), 2;
  const Real scale = 1 / (va + vb + vc);
  nearest = a + ab * (vb * scale) + ac * (vc * scale);
  return 0;
}

bool touches_own_normal(const MeshTriangle& triangle, int part) {
  if (part == 0) return true;
  if (part <= 3) return triangle.convex_edges >> (part - 1) & 1;
  const int corner = part - 4;  // edges `corner` (from it) and `corner + 2` (to it)
  return (triangle.convex_edges >> corner & 1) || (triangle.convex_edges >> ((corner + 2) % 3) & 1);
}

}  // namespace impulse::physics
