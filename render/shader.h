// A linked GLSL program built from source, with compile/link logs in the exception text,
// and typed uniform setters (direct state access: the program need not be bound).
#pragma once
#include <Eigen/Core>
#include <string>
#include <string_view>

#include "render/gl_objects.h"

namespace impulse::render {

class ShaderProgram {
 public:
  // `name` only labels error messages. An empty fragment source builds a depth-only program.
  // Throws std::runtime_error with the driver's log on a compile or link error.
  ShaderProgram(std::string_view name, std::string_view vertex_source, std::string_view fragment_source);

  GLuint id() const { return program_.id(); }
  void use() const { glUseProgram(program_.id()); }

  // Setting a uniform the linker optimised away is a silent no-op, as in GL.
  void set(const char* uniform, int value) const;
  void set(const char* uniform, float value) const;
  void set(const char* uniform, const Eigen::Vector3f& value) const;
  void set(const char* uniform, const Eigen::Matrix4f& value) const;

 private:
  GLint location(const char* uniform) const { return glGetUniformLocation(program_.id(), uniform); }

  std::string name_;
  GlProgram program_;
};

}  // namespace impulse::render
