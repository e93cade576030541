#include "render/shader.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace impulse::render {
namespace {

// A shader object that deletes itself; it only lives until the program is linked.
class ShaderObject {
 public:
  explicit ShaderObject(GLenum stage) : id_(glCreateShader(stage)) {}
  ~ShaderObject() { glDeleteShader(id_); }
  ShaderObject(const ShaderObject&) = delete;
  ShaderObject& operator=(const ShaderObject&) = delete;
  GLuint id() const { return id_; }

 private:
  GLuint id_;
};

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log.data();
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return log.data();
}

void compile(const ShaderObject& shader, std::string_view source, const std::string& label) {
  const GLchar* text = source.data();
  const auto length = static_cast<GLint>(source.size());
  glShaderSource(shader.id(), 1, &text, &length);
  glCompileShader(shader.id());
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
  if (compiled != GL_TRUE) {
    throw std::runtime_error("shader '" + label + "' failed to compile:\n" + shader_log(shader.id()));
  }
}

}  // namespace

ShaderProgram::ShaderProgram(std::string_view name, std::string_view vertex_source,
                             std::string_view fragment_source)
    : name_(name) {
  ShaderObject vertex(GL_VERTEX_SHADER);
  compile(vertex, vertex_source, name_ + ".vert");
  glAttachShader(program_.id(), vertex.id());

  ShaderObject fragment(GL_FRAGMENT_SHADER);
  if (!fragment_source.empty()) {
    compile(fragment, fragment_source, name_ + ".frag");
    glAttachShader(program_.id(), fragment.id());
  }

  glLinkProgram(program_.id());
  GLint linked = GL_FALSE;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &linked);
  glDetachShader(program_.id(), vertex.id());
  if (!fragment_source.empty()) glDetachShader(program_.id(), fragment.id());
  if (linked != GL_TRUE) {
    throw std::runtime_error("shader program '" + name_ + "' failed to link:\n" + program_log(program_.id()));
  }
}

void ShaderProgram::set(const char* uniform, int value) const {
  glProgramUniform1i(program_.id(), location(uniform), value);
}

void ShaderProgram::set(const char* uniform, float value) const {
  glProgramUniform1f(program_.id(), location(uniform), value);
}

void ShaderProgram::set(const char* uniform, const Eigen::Vector3f& value) const {
  glProgramUniform3fv(program_.id(), location(uniform), 1, value.data());
}

void ShaderProgram::set(const char* uniform, const Eigen::Matrix4f& value) const {
  // Eigen is column-major like GLSL, so no transpose.
  glProgramUniformMatrix4fv(program_.id(), location(uniform), 1, GL_FALSE, value.data());
}

}  // namespace impulse::render
