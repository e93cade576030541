// RAII owners for cairo's surface and drawing context. Including this needs cairo's headers:
// link PkgConfig::CAIRO.
#pragma once
#include <cairo.h>

#include <memory>

namespace impulse::render::cairo {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
  void operator()(cairo_t* context) const { cairo_destroy(context); }
};

using SurfaceHandle = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextHandle = std::unique_ptr<cairo_t, ContextDeleter>;

}  // namespace impulse::render::cairo
