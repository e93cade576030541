// An offscreen OpenGL 4.5 core context, from EGL (a GPU's, or Mesa's llvmpipe through the
// surfaceless platform) or from OSMesa (llvmpipe; gone from Mesa 25.1, so optional at build
// time). Real rendering goes to framebuffer objects: neither backend needs a window or a display.
// A context is current per thread: call make_current() before using GL on another context.
//
// Every GL call goes through glad's pointers (render/gl.h), loaded from the backend's own
// get-proc-address when a context is first made current: one process draws with one backend.
#pragma once
#include <memory>
#include <string>
#include <string_view>

namespace impulse::render {

enum class GlBackend { automatic, egl, osmesa };

// "auto", "egl", "osmesa" (as --gl and IMPULSE_GL spell them); throws std::invalid_argument
// naming the three on anything else.
GlBackend parse_gl_backend(std::string_view name);
const char* gl_backend_name(GlBackend backend);
// IMPULSE_GL, or automatic when unset or empty; throws as parse_gl_backend does.
GlBackend gl_backend_from_environment();
// IMPULSE_GPU: which hardware EGL device to draw on (0 the first), -1 when unset.
int gpu_from_environment();
// Whether this build has the OSMesa backend.
bool osmesa_built();
// How many hardware devices (GPUs) EGL lists here; 0 where it lists none or there is no EGL.
int egl_gpu_count();

// What a context drew with: the backend chosen, and OpenGL's own words for it.
struct GlInfo {
  GlBackend backend = GlBackend::automatic;  // egl or osmesa once made
  std::string device;                        // "surfaceless (software)", "EGL device 0 (hardware)", "OSMesa"
  std::string renderer;                      // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;                       // GL_VERSION
};

class GlContext {
 public:
  // automatic: EGL, else OSMesa where it is built (the reason EGL failed is kept in the error
  // when both fail). gpu: the hardware EGL device to use (-1: the first hardware device, else
  // software). Creates the context and makes it current; throws std::runtime_error saying what
  // to install or set.
  explicit GlContext(GlBackend backend = gl_backend_from_environment(), int gpu = gpu_from_environment());
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void make_current();  // throws std::runtime_error
  const GlInfo& info() const { return info_; }

  // The two backends, behind one interface (gl_egl.cpp, gl_osmesa.cpp).
  struct Backend;

 private:
  std::unique_ptr<Backend> backend_;
  GlInfo info_;
};

}  // namespace impulse::render
