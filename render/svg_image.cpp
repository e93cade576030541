#include "render/svg_image.h"

#include <librsvg/rsvg.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace impulse::render {
namespace {

struct HandleDeleter {
  void operator()(RsvgHandle* handle) const { g_object_unref(handle); }
};
struct ErrorDeleter {
  void operator()(GError* error) const { g_error_free(error); }
};
using HandlePtr = std::unique_ptr<RsvgHandle, HandleDeleter>;
using ErrorPtr = std::unique_ptr<GError, ErrorDeleter>;

// `svg` with a style that strokes its paths `width` wide, after its opening tag.
std::string emboldened(const std::string& svg, double width) {
  const size_t opening = svg.find("<svg");
  const size_t end = opening == std::string::npos ? opening : svg.find('>', opening);
  if (end == std::string::npos || !(width > 0)) return svg;
  char style[160];
  std::snprintf(style, sizeof style, "<style>path{stroke:#000;stroke-width:%.3f;stroke-linejoin:round}</style>", width);
  return svg.substr(0, end + 1) + style + svg.substr(end + 1);
}

}  // namespace

SvgRaster rasterise_svg(const std::string& original, double pixels_per_point, double embolden) {
  const std::string svg = emboldened(original, embolden);
  GError* raw_error = nullptr;
  HandlePtr handle(rsvg_handle_new_from_data(reinterpret_cast<const guint8*>(svg.data()), svg.size(), &raw_error));
  ErrorPtr error(raw_error);
  if (!handle) throw std::runtime_error("overlay: librsvg cannot read an SVG: " + std::string(error ? error->message : "?"));
  rsvg_handle_set_dpi(handle.get(), 72.0);  // one point is one unit
  double width_points = 0, height_points = 0;
  if (!rsvg_handle_get_intrinsic_size_in_pixels(handle.get(), &width_points, &height_points))
    throw std::runtime_error("overlay: an SVG without a size");
  const double width = width_points * pixels_per_point, height = height_points * pixels_per_point;
  SvgRaster raster;
  raster.width = int(std::ceil(width)) + 2;
  raster.height = int(std::ceil(height)) + 2;
  raster.surface.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, raster.width, raster.height));
  if (cairo_surface_status(raster.surface.get()) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("overlay: cairo cannot make an image for an SVG");
  const cairo::ContextHandle context(cairo_create(raster.surface.get()));
  const RsvgRectangle viewport{1.0, 1.0, width, height};
  if (!rsvg_handle_render_document(handle.get(), context.get(), &viewport, &raw_error)) {
    error.reset(raw_error);
    throw std::runtime_error("overlay: librsvg cannot draw an SVG: " + std::string(error ? error->message : "?"));
  }
  cairo_surface_flush(raster.surface.get());
  return raster;
}

}  // namespace impulse::render
