// An offscreen OpenGL 4.5 core context from OSMesa (software, llvmpipe). It owns a tiny RGBA
// buffer it is made current on; real rendering goes to framebuffer objects.
// A context is current per thread: call make_current() before using GL on another context.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

struct osmesa_context;  // OSMesaContext is `osmesa_context*`

namespace impulse::render {

class GlContext {
 public:
  GlContext();  // creates the context and makes it current; throws std::runtime_error
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void make_current();               // throws std::runtime_error

 private:
  static constexpr int kBufferSize = 16;
  osmesa_context* context_ = nullptr;
  std::vector<uint32_t> default_buffer_;  // RGBA, kBufferSize x kBufferSize; uint32_t keeps it 4-aligned
};

}  // namespace impulse::render
