#include "render/gl_context.h"

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

#include "render/gl.h"
#include "render/gl_backend.h"
#include "render/shader_cache.h"

namespace impulse::render {
namespace {

// glad's pointers are the process's: loaded from the first context's backend, and again only if
// a context of the other backend is made current.
std::mutex loading;
GlLoader loaded_from = nullptr;

void load_gl(GlLoader loader) {
  const std::lock_guard lock(loading);
  if (loaded_from == loader) return;
  if (gladLoadGL(reinterpret_cast<GLADloadfunc>(loader)) < GLAD_MAKE_VERSION(4, 5))
    throw std::runtime_error("OpenGL: the context does not give OpenGL 4.5's entry points");
  loaded_from = loader;
}

std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text != nullptr ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

GlBackend parse_gl_backend(std::string_view name) {
  if (name == "auto") return GlBackend::automatic;
  if (name == "egl") return GlBackend::egl;
  if (name == "osmesa") return GlBackend::osmesa;
  throw std::invalid_argument("the OpenGL backend is auto, egl or osmesa, not '" + std::string(name) + "'");
}

const char* gl_backend_name(GlBackend backend) {
  switch (backend) {
    case GlBackend::automatic: return "auto";
    case GlBackend::egl: return "egl";
    case GlBackend::osmesa: return "osmesa";
  }
  return "auto";
}

GlBackend gl_backend_from_environment() {
  const char* value = std::getenv("IMPULSE_GL");
  if (value == nullptr || *value == '\0') return GlBackend::automatic;
  try {
    return parse_gl_backend(value);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("IMPULSE_GL: ") + error.what());
  }
}

int gpu_from_environment() {
  const char* value = std::getenv("IMPULSE_GPU");
  if (value == nullptr || *value == '\0') return -1;
  char* end = nullptr;
  const long gpu = std::strtol(value, &end, 10);
  if (*end != '\0' || gpu < 0 || gpu > 255)
    throw std::invalid_argument(std::string("IMPULSE_GPU: a device number from 0, not '") + value + "'");
  return int(gpu);
}

GlContext::GlContext(GlBackend backend, int gpu) {
  separate_shader_cache_by_vector_width();  // before llvmpipe opens its cache
  if (backend == GlBackend::osmesa) {
    backend_ = make_osmesa_backend();
  } else if (backend == GlBackend::egl || !osmesa_built()) {
    backend_ = make_egl_backend(gpu);
  } else {
    try {
      backend_ = make_egl_backend(gpu);
    } catch (const std::runtime_error& egl) {
      if (gpu >= 0) throw;
      try {
        backend_ = make_osmesa_backend();
      } catch (const std::runtime_error& osmesa) {
        throw std::runtime_error(std::string(egl.what()) + "; and " + osmesa.what());
      }
    }
  }
  load_gl(backend_->loader());
  info_ = {backend_->kind, backend_->device, gl_string(GL_RENDERER), gl_string(GL_VERSION)};
}

GlContext::~GlContext() = default;

void GlContext::make_current() {
  backend_->make_current();
  load_gl(backend_->loader());
}

}  // namespace impulse::render
