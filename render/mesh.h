// Unit meshes as plain vertex data, counter-clockwise outward-facing triangles:
// the renderer scales and places them per instance.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace impulse::render {

// `outline`: for make_flat_mesh, one value a side of the vertex's triangle (the one across from each
// corner in turn), 0 along that side and affine across the triangle where the side outlines a face,
// else 1 throughout; the edge anti-aliasing and the edge lines take it (shaders.cpp, kFaceMesh).
// The other meshes have their outlines in their coordinates and leave it 1.
struct MeshVertex {
  float position[3];
  float normal[3];
  float outline[3];
};

struct MeshData {
  std::vector<MeshVertex> vertices;
  std::vector<uint32_t> indices;  // triangles
};

MeshData make_icosphere(int subdivisions);  // radius 1, smooth normals; 20 * 4^subdivisions triangles
MeshData make_cube();                       // [-1, 1]^3, flat normals
// Radius 1 about the y axis, y in [-1, 1]: `segments` (>= 3) flat sides with smooth normals and two
// flat caps, 4 * segments triangles.
MeshData make_cylinder(int segments);
MeshData make_quad();                       // [-1, 1]^2 in x, z at y = 0, facing +y
// The triangles of `corners` (three a triangle, counter-clockwise seen from outside) as they are,
// each with its own flat normal; a side is a face's outline unless the triangle across it lies in
// the same plane. Triangles without area are left out.
MeshData make_flat_mesh(const std::vector<Eigen::Vector3f>& corners);

}  // namespace impulse::render
