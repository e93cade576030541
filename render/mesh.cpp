#include "render/mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace impulse::render {
namespace {

using Vec3 = Eigen::Vector3f;

uint32_t add_vertex(MeshData& mesh, const Vec3& position, const Vec3& normal, const Vec3& outline = Vec3::Ones()) {
  mesh.vertices.push_back({{position.x(), position.y(), position.z()},
                           {normal.x(), normal.y(), normal.z()},
                           {outline.x(), outline.y(), outline.z()}});
  return static_cast<uint32_t>(mesh.vertices.size() - 1);
}

void add_triangle(MeshData& mesh, uint32_t a, uint32_t b, uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

}  // namespace

MeshData make_icosphere(int subdivisions) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<Vec3> points = {
      {-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : points) p.normalize();
  std::vector<uint32_t> triangles = {0, 11, 5, 0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                     4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9,  4, 3,  4,  2, 3, 2, 6, 3,
                                     6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6, 2, 10, 8,  6, 7, 9, 8, 1};

  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      if (auto found = midpoints.find(key); found != midpoints.end()) return found->second;
      points.push_back((points[a] + points[b]).normalized());
      const auto index = static_cast<uint32_t>(points.size() - 1);
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<uint32_t> finer;
    finer.reserve(triangles.size() * 4);
    for (size_t i = 0; i < triangles.size(); i += 3) {
      const uint32_t a = triangles[i], b = triangles[i + 1], c = triangles[i + 2];
      const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    triangles = std::move(finer);
  }

  MeshData mesh;
  mesh.vertices.reserve(points.size());
  for (const Vec3& p : points) add_vertex(mesh, p, p);
  mesh.indices = std::move(triangles);
  return mesh;
}

MeshData make_cube() {
  MeshData mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = sign;
      // u, v span the face so that u x v = normal (counter-clockwise seen from outside).
      Vec3 u = Vec3::Zero(), v = Vec3::Zero();
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = sign;
      const uint32_t first = add_vertex(mesh, normal - u - v, normal);
      add_vertex(mesh, normal + u - v, normal);
      add_vertex(mesh, normal + u + v, normal);
      add_vertex(mesh, normal - u + v, normal);
      add_triangle(mesh, first, first + 1, first + 2);
      add_triangle(mesh, first, first + 2, first + 3);
    }
  }
  return mesh;
}

MeshData make_cylinder(int segments) {
  segments = std::max(segments, 3);
  MeshData mesh;
  std::vector<Vec3> rim;  // at y = 0, counter-clockwise seen from +y
  for (int i = 0; i < segments; ++i) {
    const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(segments);
    rim.emplace_back(std::cos(angle), 0.0f, -std::sin(angle));
  }
  // The side: a bottom and a top vertex at each rim point, normal straight out; the seam shares them.
  for (const Vec3& p : rim) {
    add_vertex(mesh, p - Vec3::UnitY(), p);
    add_vertex(mesh, p + Vec3::UnitY(), p);
  }
  const auto n = static_cast<uint32_t>(segments);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t bottom = 2 * i, top = 2 * i + 1, next_bottom = 2 * ((i + 1) % n), next_top = next_bottom + 1;
    add_triangle(mesh, bottom, next_bottom, next_top);
    add_triangle(mesh, bottom, next_top, top);
  }
  // The caps: fans about their centres, with their own vertices for the flat normals.
  for (const float y : {-1.0f, 1.0f}) {
    const Vec3 normal(0.0f, y, 0.0f);
    const uint32_t centre = add_vertex(mesh, normal, normal);
    for (const Vec3& p : rim) add_vertex(mesh, p + normal, normal);
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = centre + 1 + i, b = centre + 1 + (i + 1) % n;
      if (y > 0) add_triangle(mesh, centre, a, b);
      else add_triangle(mesh, centre, b, a);
    }
  }
  return mesh;
}

MeshData make_quad() {
  MeshData mesh;
  const Vec3 up = Vec3::UnitY();
  add_vertex(mesh, Vec3(-1.0f, 0.0f, -1.0f), up);
  add_vertex(mesh, Vec3(-1.0f, 0.0f, 1.0f), up);
  add_vertex(mesh, Vec3(1.0f, 0.0f, 1.0f), up);
  add_vertex(mesh, Vec3(1.0f, 0.0f, -1.0f), up);
  add_triangle(mesh, 0, 1, 2);
  add_triangle(mesh, 0, 2, 3);
  return mesh;
}

MeshData make_flat_mesh(const std::vector<Vec3>& corners) {
  // Triangles meeting at less than this (cosine of 5 degrees) are one surface, no line between
  // them: a fan across a flat polygon rounds its normals apart by far less, a mesh's curved
  // surface (a half-pipe's strips, 1.25 degrees apart) would be ruled with lines, and a
  // polyhedron's faces meet at far more (a 16-sided prism's at 22.5).
  constexpr float kSamePlane = 0.99619f;
  const size_t count = corners.size() / 3;
  std::vector<Vec3> normals(count, Vec3::Zero());
  for (size_t t = 0; t < count; ++t) {
    const Vec3& a = corners[3 * t];
    const Vec3 facing = (corners[3 * t + 1] - a).cross(corners[3 * t + 2] - a);
    if (facing.norm() > 0.0f) normals[t] = facing.normalized();  // a NaN corner fails too
  }
  // Each triangle's sides as they run round it, (from, to): the neighbour across a side has it as
  // (to, from).
  using Side = std::array<float, 6>;
  auto side = [&](size_t from, size_t to) {
    const Vec3 &p = corners[from], &q = corners[to];
    return Side{p.x(), p.y(), p.z(), q.x(), q.y(), q.z()};
  };
  std::map<Side, size_t> triangle_of;
  for (size_t t = 0; t < count; ++t)
    for (size_t k = 0; k < 3; ++k) triangle_of.emplace(side(3 * t + k, 3 * t + (k + 1) % 3), t);

  MeshData mesh;
  mesh.vertices.reserve(corners.size());
  mesh.indices.reserve(corners.size());
  for (size_t t = 0; t < count; ++t) {
    if (normals[t].isZero()) continue;
    Vec3 outlines = Vec3::Zero();  // 1 where the side across from that corner outlines nothing
    for (size_t k = 0; k < 3; ++k) {
      const auto across = triangle_of.find(side(3 * t + (k + 2) % 3, 3 * t + (k + 1) % 3));
      const bool same_face = across != triangle_of.end() && normals[across->second].dot(normals[t]) > kSamePlane;
      outlines[Eigen::Index(k)] = same_face ? 1.0f : 0.0f;
    }
    for (size_t k = 0; k < 3; ++k) {
      Vec3 outline = outlines;  // a barycentric coordinate where a side outlines, 1 elsewhere
      outline[Eigen::Index(k)] = 1.0f;
      mesh.indices.push_back(add_vertex(mesh, corners[3 * t + k], normals[t], outline));
    }
  }
  return mesh;
}

}  // namespace impulse::render
