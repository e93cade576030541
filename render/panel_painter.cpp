#include "render/panel_painter.h"

#include "render/cairo_shapes.h"
#include "render/overlay_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::render {
namespace {

const Colour kInk{0.13f, 0.13f, 0.15f};  // as the overlay's other text
constexpr size_t kMostRasters = 256;      // distinct texts × sizes kept; a lecture shows a handful
constexpr double kFewestPixelsPerPoint = 1.0;
constexpr double kEmbolden = 0.25;        // TeX points of stroke round each glyph: legible at 480 lines

struct Metrics {
  double size, line, pad, gap;
};
Metrics metrics(double scale) { return {15 * scale, 15 * scale * 1.4, 10 * scale, 6 * scale}; }

void set_line_font(cairo_t* cr, double size, bool heading) { set_font(cr, size, heading, !heading); }

}  // namespace

const SvgRaster* PanelPainter::raster(const OverlayMath& math, double scale) {
  if (!math.svg) return nullptr;
  // Never under a pixel a point: 12 pt letters smaller than 12 pixels lose their subscripts.
  const double pixels_per_point = std::max(double(math.pixels_per_point) * scale, kFewestPixelsPerPoint);
  char size[32];
  std::snprintf(size, sizeof size, "@%.4f", pixels_per_point);
  const std::string key = math.key + size;
  if (const auto found = rasters_.find(key); found != rasters_.end()) return &found->second;
  if (rasters_.size() >= kMostRasters) rasters_.clear();
  return &rasters_.emplace(key, rasterise_svg(*math.svg, pixels_per_point, kEmbolden)).first->second;
}

PanelPainter::Size PanelPainter::measure(cairo_t* cr, const OverlayPanel& panel, double scale) {
  const Metrics m = metrics(scale);
  Size size;
  for (size_t i = 0; i < panel.lines.size(); ++i) {
    set_line_font(cr, m.size, i == 0);
    size.width = std::max(size.width, text_width(cr, panel.lines[i]));
  }
  size.height = panel.lines.empty() ? 0 : m.line * panel.lines.size() - 0.3 * m.line;
  if (const SvgRaster* math = raster(panel.math, scale)) {
    size.width = std::max(size.width, double(math->width));
    size.height += (panel.lines.empty() ? 0 : m.gap) + math->height;
  }
  size.width += 2 * m.pad;
  size.height += 2 * m.pad;
  return size;
}

void PanelPainter::paint_content(cairo_t* cr, const OverlayPanel& panel, double x, double y, double scale,
                                 const Size& size) {
  const Metrics m = metrics(scale);
  panel_box(cr, x, y, size.width, size.height, 8 * scale, 0.9);
  for (size_t i = 0; i < panel.lines.size(); ++i) {
    set_line_font(cr, m.size, i == 0);
    const Colour& colour = i == 0 ? panel.colour : kInk;
    cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
    cairo_move_to(cr, x + m.pad, y + m.pad + m.size * 0.9 + m.line * i);
    show_text(cr, panel.lines[i]);
  }
  if (const SvgRaster* math = raster(panel.math, scale)) {
    const double top = y + m.pad + (panel.lines.empty() ? 0 : m.line * panel.lines.size() - 0.3 * m.line + m.gap);
    // Whole pixels: the raster was made for the pixel grid, and stays as crisp as it was made.
    cairo_set_source_rgb(cr, kInk.r, kInk.g, kInk.b);
    cairo_mask_surface(cr, math->surface.get(), std::round(x + m.pad - 1), std::round(top - 1));
  }
}

void PanelPainter::paint(cairo_t* cr, const OverlayPanel& panel, double x, double y, double scale) {
  const Size size = measure(cr, panel, scale);
  const double opacity = std::clamp(double(panel.opacity), 0.0, 1.0);
  if (opacity <= 0) return;
  if (opacity >= 1) {
    paint_content(cr, panel, x, y, scale, size);
    return;
  }
  cairo_push_group(cr);
  paint_content(cr, panel, x, y, scale, size);
  cairo_pop_group_to_source(cr);
  cairo_paint_with_alpha(cr, opacity);
}

}  // namespace impulse::render
