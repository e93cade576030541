// A "mesh" body's file: a Wavefront OBJ's triangles (tinyobjloader), for a static floor, bowl or
// half-pipe.
#include "demos/scene/scene_sections.h"

#include <tiny_obj_loader.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>

namespace impulse::demos {

namespace fs = std::filesystem;

namespace {

// More triangles than a lecture's surface needs, and than the narrow phase keeps quick; a larger
// file than such a mesh takes (about 40 bytes a vertex or face) is refused before it is read.
constexpr size_t kMostTriangles = 200000;
constexpr std::uintmax_t kLargestFile = 64u << 20;

}  // namespace

std::shared_ptr<const physics::Mesh> read_mesh_file(const std::string& path, double scale) {
  std::error_code error;
  if (!fs::is_regular_file(path, error))
    throw std::runtime_error("no file " + path + (fs::exists(path, error) ? " (it is not a file)" : "") +
                             ": give a Wavefront .obj file, its path from the scene file's folder");
  if (const std::uintmax_t size = fs::file_size(path, error); !error && size > kLargestFile)
    throw std::runtime_error(path + " is " + std::to_string(size >> 20) + " MiB, more than a mesh of " +
                             std::to_string(kMostTriangles) + " triangles takes: simplify it (e.g. Blender's Decimate)");
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = fs::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    throw std::runtime_error("cannot read " + path + " as a Wavefront OBJ file" + (why.empty() ? "" : ": " + why));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  std::vector<physics::Vec3> vertices;
  for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
    vertices.emplace_back(scale * attrib.vertices[i], scale * attrib.vertices[i + 1], scale * attrib.vertices[i + 2]);
  std::vector<std::array<int, 3>> triangles;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t at = 0;
    for (const unsigned char corners : shape.mesh.num_face_vertices) {
      if (corners == 3)
        triangles.push_back({shape.mesh.indices[at].vertex_index, shape.mesh.indices[at + 1].vertex_index,
                             shape.mesh.indices[at + 2].vertex_index});
      at += corners;
    }
    if (triangles.size() > kMostTriangles)
      throw std::runtime_error(path + " has more than " + std::to_string(kMostTriangles) +
                               " triangles: a lecture's surface needs fewer (simplify it, e.g. Blender's Decimate)");
  }
  if (triangles.empty()) throw std::runtime_error(path + " has no faces (f lines): a mesh is its triangles");
  try {
    return std::make_shared<const physics::Mesh>(physics::make_mesh(vertices, triangles));
  } catch (const std::invalid_argument& why) {
    throw std::runtime_error(path + ": " + why.what());
  }
}

}  // namespace impulse::demos
