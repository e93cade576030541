// Triangles of flat-coloured vertices (FlatVertex) streamed to the GPU each frame and drawn in
// one call: attribute 0 position, 1 colour, 2 outline.
#pragma once
#include <vector>

#include "render/flat_arrows.h"
#include "render/gl_objects.h"

namespace impulse::render {

class FlatMesh {
 public:
  FlatMesh();
  void upload(const std::vector<FlatVertex>& triangles);
  void draw() const;  // draws what the last upload() sent, with the currently bound program

 private:
  GlVertexArray vertex_array_;
  GlBuffer vertex_buffer_;
  GLsizei vertex_count_ = 0;
};

}  // namespace impulse::render
