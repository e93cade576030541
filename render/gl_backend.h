// The interface each GL backend implements for GlContext (gl_context.cpp): make its context
// current, and hand glad the function that finds GL's entry points in its library.
#pragma once
#include <memory>
#include <string>

#include "render/gl_context.h"

namespace impulse::render {

using GlProc = void (*)();
using GlLoader = GlProc (*)(const char* name);

struct GlContext::Backend {
  virtual ~Backend() = default;
  virtual void make_current() = 0;  // throws std::runtime_error
  virtual bool is_current() const = 0;
  virtual GlLoader loader() const = 0;
  GlBackend kind = GlBackend::automatic;
  std::string device;
};

// Each throws std::runtime_error saying why it cannot (and what to install or set).
std::unique_ptr<GlContext::Backend> make_egl_backend(int gpu);
std::unique_ptr<GlContext::Backend> make_osmesa_backend();

}  // namespace impulse::render
