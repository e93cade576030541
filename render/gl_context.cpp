#include "render/gl_context.h"

#include <GL/osmesa.h>  // brings GL/gl.h; the rest of render/ uses GL/glcorearb.h instead

#include <stdexcept>

#include "render/shader_cache.h"

namespace impulse::render {

GlContext::GlContext() : default_buffer_(kBufferSize * kBufferSize, 0u) {
  separate_shader_cache_by_vector_width();  // before llvmpipe opens its cache
  const int attributes[] = {
      OSMESA_FORMAT,                OSMESA_RGBA,
      OSMESA_DEPTH_BITS,            24,
      OSMESA_STENCIL_BITS,          0,
      OSMESA_ACCUM_BITS,            0,
      OSMESA_PROFILE,               OSMESA_CORE_PROFILE,
      OSMESA_CONTEXT_MAJOR_VERSION, 4,
      OSMESA_CONTEXT_MINOR_VERSION, 5,
      0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw std::runtime_error(
        "OSMesa: cannot create an OpenGL 4.5 core profile context "
        "(needs Mesa >= 20 with the llvmpipe driver; check GALLIUM_DRIVER is unset or llvmpipe)");
  }
  make_current();
}

GlContext::~GlContext() {
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
}

void GlContext::make_current() {
  if (OSMesaGetCurrentContext() == context_) return;
  if (!OSMesaMakeCurrent(context_, default_buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize, kBufferSize)) {
    throw std::runtime_error("OSMesa: cannot make the offscreen context current");
  }
}

}  // namespace impulse::render
