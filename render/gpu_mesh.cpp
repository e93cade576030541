#include "render/gpu_mesh.h"

#include <cstddef>

namespace impulse::render {
namespace {

constexpr GLuint kVertexBinding = 0;
constexpr GLuint kInstanceBinding = 1;

// Vertex attribute binding (GL 4.3): format and source buffer are set separately.
void float_attribute(GLuint location, GLint components, size_t offset, GLuint binding) {
  glEnableVertexAttribArray(location);
  glVertexAttribFormat(location, components, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offset));
  glVertexAttribBinding(location, binding);
}

}  // namespace

GpuMesh::GpuMesh(const MeshData& mesh) : index_count_(static_cast<GLsizei>(mesh.indices.size())) {
  glBindVertexArray(vertex_array_.id());

  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(MeshVertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.id());  // recorded in the vertex array
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);

  glBindVertexBuffer(kVertexBinding, vertex_buffer_.id(), 0, sizeof(MeshVertex));
  float_attribute(0, 3, offsetof(MeshVertex, position), kVertexBinding);
  float_attribute(1, 3, offsetof(MeshVertex, normal), kVertexBinding);
  float_attribute(11, 3, offsetof(MeshVertex, outline), kVertexBinding);

  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof(Instance), nullptr, GL_STREAM_DRAW);  // makes the name a buffer
  glBindVertexBuffer(kInstanceBinding, instance_buffer_.id(), 0, sizeof(Instance));
  glVertexBindingDivisor(kInstanceBinding, 1);
  for (GLuint column = 0; column < 4; ++column) {
    float_attribute(2 + column, 4, offsetof(Instance, model) + column * 4 * sizeof(float), kInstanceBinding);
  }
  for (GLuint column = 0; column < 3; ++column) {
    float_attribute(6 + column, 3, offsetof(Instance, normal_matrix) + column * 3 * sizeof(float),
                    kInstanceBinding);
  }
  float_attribute(9, 3, offsetof(Instance, colour), kInstanceBinding);
  float_attribute(10, 1, offsetof(Instance, style), kInstanceBinding);

  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GpuMesh::upload(const std::vector<Instance>& instances) {
  instance_count_ = static_cast<GLsizei>(instances.size());
  if (instances.empty()) return;
  // Re-specifying the whole store each frame lets the driver orphan the old one.
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(Instance)), instances.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void GpuMesh::draw() const {
  if (instance_count_ == 0) return;
  glBindVertexArray(vertex_array_.id());
  glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, instance_count_);
  glBindVertexArray(0);
}

}  // namespace impulse::render
