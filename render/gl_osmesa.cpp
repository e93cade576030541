// The OSMesa backend: Mesa's llvmpipe into a tiny buffer of ours (real drawing goes to
// framebuffer objects). Built where Mesa still has OSMesa (Debian 12 and 13; gone from Mesa 25.1).
#include "render/gl_backend.h"

#include <cstdint>
#include <stdexcept>
#include <vector>

#if IMPULSE_OSMESA
#include <GL/osmesa.h>  // brings GL/gl.h: this file never includes render/gl.h
#endif

namespace impulse::render {

#if IMPULSE_OSMESA

namespace {

class OsmesaBackend final : public GlContext::Backend {
 public:
  OsmesaBackend() : buffer_(kBufferSize * kBufferSize, 0u) {
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
    if (context_ == nullptr)
      throw std::runtime_error(
          "OSMesa: cannot create an OpenGL 4.5 core profile context "
          "(needs Mesa >= 20 with the llvmpipe driver; check GALLIUM_DRIVER is unset or llvmpipe)");
    kind = GlBackend::osmesa;
    device = "OSMesa";
    make_current();
  }
  ~OsmesaBackend() override {
    if (is_current()) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
  }
  void make_current() override {
    if (is_current()) return;
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize, kBufferSize))
      throw std::runtime_error("OSMesa: cannot make the offscreen context current");
  }
  bool is_current() const override { return OSMesaGetCurrentContext() == context_; }
  GlLoader loader() const override { return [](const char* name) { return GlProc(OSMesaGetProcAddress(name)); }; }

 private:
  static constexpr int kBufferSize = 16;
  OSMesaContext context_ = nullptr;
  std::vector<uint32_t> buffer_;  // RGBA, kBufferSize x kBufferSize; uint32_t keeps it 4-aligned
};

}  // namespace

std::unique_ptr<GlContext::Backend> make_osmesa_backend() { return std::make_unique<OsmesaBackend>(); }
bool osmesa_built() { return true; }

#else

std::unique_ptr<GlContext::Backend> make_osmesa_backend() {
  throw std::runtime_error("OSMesa: this impulse was built without it (cmake -DIMPULSE_OSMESA=ON, with libosmesa6-dev)");
}
bool osmesa_built() { return false; }

#endif

}  // namespace impulse::render
