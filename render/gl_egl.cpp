// The EGL backend: a GPU's EGL device where there is one (EGL_EXT_platform_device), else Mesa's
// llvmpipe through the surfaceless platform (EGL_MESA_platform_surfaceless): no window, no
// display server, no /dev/dri needed. The context is made current with no surface
// (EGL_KHR_surfaceless_context); drawing goes to framebuffer objects.
#include "render/gl_backend.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace impulse::render {
namespace {

std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", unsigned(eglGetError()));
  return std::string("EGL: ") + what + " (error " + code + ")";
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t length = std::strlen(name);
  for (const char* at = std::strstr(list, name); at != nullptr; at = std::strstr(at + length, name))
    if ((at == list || at[-1] == ' ') && (at[length] == ' ' || at[length] == '\0')) return true;
  return false;
}

template <typename F>
F proc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

// The hardware devices EGL lists (Mesa's software device left out), in its order.
std::vector<EGLDeviceEXT> hardware_devices() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_device_enumeration") && !has_extension(client, "EGL_EXT_device_base")) return {};
  const auto query_devices = proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  const auto query_string = proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (query_devices == nullptr || query_string == nullptr) return {};
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  if (!query_devices(count, devices.data(), &count)) return {};
  devices.resize(size_t(count));
  std::vector<EGLDeviceEXT> hardware;
  for (EGLDeviceEXT device : devices)
    if (!has_extension(query_string(device, EGL_EXTENSIONS), "EGL_MESA_device_software")) hardware.push_back(device);
  return hardware;
}

class EglBackend final : public GlContext::Backend {
 public:
  // A context on `display`, initialised here; throws on any failure.
  EglBackend(EGLDisplay display, std::string name) : display_(display) {
    if (display_ == EGL_NO_DISPLAY) throw std::runtime_error(egl_error(("no display for " + name).c_str()));
    if (!eglInitialize(display_, nullptr, nullptr)) throw std::runtime_error(egl_error(("cannot initialise " + name).c_str()));
    const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
    if (!has_extension(extensions, "EGL_KHR_surfaceless_context"))
      throw std::runtime_error("EGL: " + name + " cannot draw without a surface (EGL_KHR_surfaceless_context)");
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("desktop OpenGL is not offered"));
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
      const EGLint wanted[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint count = 0;
      if (!eglChooseConfig(display_, wanted, &config, 1, &count) || count < 1)
        throw std::runtime_error(egl_error(("no OpenGL configuration on " + name).c_str()));
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT)
      throw std::runtime_error(egl_error(("cannot create an OpenGL 4.5 core context on " + name).c_str()));
    kind = GlBackend::egl;
    device = std::move(name);
    make_current();
  }
  // The display stays initialised: other contexts of the process share it (EGL returns one
  // display per platform and device).
  ~EglBackend() override {
    if (is_current()) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  void make_current() override {
    if (is_current()) return;
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error(egl_error("cannot make the context current"));
  }
  bool is_current() const override { return eglGetCurrentContext() == context_; }
  GlLoader loader() const override { return [](const char* name) { return GlProc(eglGetProcAddress(name)); }; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

std::unique_ptr<GlContext::Backend> software() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_MESA_platform_surfaceless"))
    throw std::runtime_error("EGL: Mesa's surfaceless platform is missing (install libegl-mesa0)");
  const auto platform_display = proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (platform_display == nullptr) throw std::runtime_error("EGL: eglGetPlatformDisplayEXT is missing");
  return std::make_unique<EglBackend>(platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                                      "surfaceless (software)");
}

std::unique_ptr<GlContext::Backend> hardware(const std::vector<EGLDeviceEXT>& devices, int gpu) {
  const auto platform_display = proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (platform_display == nullptr) throw std::runtime_error("EGL: eglGetPlatformDisplayEXT is missing");
  return std::make_unique<EglBackend>(platform_display(EGL_PLATFORM_DEVICE_EXT, devices[size_t(gpu)], nullptr),
                                      "EGL device " + std::to_string(gpu) + " (hardware)");
}

}  // namespace

int egl_gpu_count() {
  if (eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS) == nullptr) return 0;
  return int(hardware_devices().size());
}

// gpu -1: the first hardware device that works, else software; gpu N: that one, or an error.
std::unique_ptr<GlContext::Backend> make_egl_backend(int gpu) {
  if (eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS) == nullptr)
    throw std::runtime_error("EGL: no client extensions (install libegl1 and libegl-mesa0)");
  const std::vector<EGLDeviceEXT> devices = hardware_devices();
  if (gpu >= 0) {
    if (gpu >= int(devices.size()))
      throw std::runtime_error("EGL: no GPU " + std::to_string(gpu) + ": this machine has " + std::to_string(devices.size()) +
                               " (leave --gpu out to draw in software)");
    return hardware(devices, gpu);
  }
  for (int i = 0; i < int(devices.size()); ++i) {
    try {
      return hardware(devices, i);
    } catch (const std::runtime_error&) {
      // the next device, then software
    }
  }
  return software();
}

}  // namespace impulse::render
