#include "render/flat_mesh.h"

#include <cstddef>

namespace impulse::render {

FlatMesh::FlatMesh() {
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof(FlatVertex), nullptr, GL_STREAM_DRAW);  // makes the name a buffer
  glBindVertexBuffer(0, vertex_buffer_.id(), 0, sizeof(FlatVertex));
  const size_t offsets[] = {offsetof(FlatVertex, position), offsetof(FlatVertex, colour), offsetof(FlatVertex, outline)};
  for (GLuint location : {0u, 1u, 2u}) {
    glEnableVertexAttribArray(location);
    glVertexAttribFormat(location, location == 2 ? 4 : 3, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offsets[location]));
    glVertexAttribBinding(location, 0);
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void FlatMesh::upload(const std::vector<FlatVertex>& triangles) {
  vertex_count_ = static_cast<GLsizei>(triangles.size());
  if (triangles.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(triangles.size() * sizeof(FlatVertex)), triangles.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void FlatMesh::draw() const {
  if (vertex_count_ == 0) return;
  glBindVertexArray(vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
  glBindVertexArray(0);
}

}  // namespace impulse::render
