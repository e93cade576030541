// Unit meshes as plain vertex data, counter-clockwise outward-facing triangles:
// the renderer scales and places them per instance.
#pragma once
#include <cstdint>
#include <vector>

namespace impulse::render {

struct MeshVertex {
  float position[3];
  float normal[3];
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

}  // namespace impulse::render
