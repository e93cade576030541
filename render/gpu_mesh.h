// A unit mesh uploaded to the GPU with a streaming per-instance buffer: one instanced draw call
// draws every item of one kind.
#pragma once
#include <vector>

#include "render/gl_objects.h"
#include "render/instance.h"
#include "render/mesh.h"

namespace impulse::render {

class GpuMesh {
 public:
  explicit GpuMesh(const MeshData& mesh);

  // Uploads `instances` and draws them with the currently bound program.
  void upload(const std::vector<Instance>& instances);
  void draw() const;  // draws what the last upload() sent; nothing if it was empty

 private:
  GlVertexArray vertex_array_;
  GlBuffer vertex_buffer_;
  GlBuffer index_buffer_;
  GlBuffer instance_buffer_;
  GLsizei index_count_ = 0;
  GLsizei instance_count_ = 0;
};

}  // namespace impulse::render
