#include "render/mesh.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace impulse::render {
namespace {

using Vec3 = Eigen::Vector3f;

uint32_t add_vertex(MeshData& mesh, const Vec3& position, const Vec3& normal) {
  mesh.vertices.push_back({{position.x(), position.y(), position.z()}, {normal.x(), normal.y(), normal.z()}});
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

}  // namespace impulse::render
