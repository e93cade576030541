// Paints an OverlayPanel (overlay.h): its lines of text in DejaVu Sans (the heading bold, the rest
// monospace) and under them its typeset mathematics, on a white rounded box. Each SVG is
// rasterised once per size (svg_image.h) and kept, so a panel shown for many frames costs a
// mask paint a frame. One per overlay painter (not thread-safe).
#pragma once
#include "render/overlay.h"
#include "render/svg_image.h"

#include <map>
#include <string>

namespace impulse::render {

class PanelPainter {
 public:
  struct Size {
    double width = 0, height = 0;
  };
  // The box's size at `scale` (1 at 720 lines).
  Size measure(cairo_t* cr, const OverlayPanel& panel, double scale);
  // Paints the box with its top-left corner at (x, y).
  void paint(cairo_t* cr, const OverlayPanel& panel, double x, double y, double scale);

 private:
  const SvgRaster* raster(const OverlayMath& math, double scale);  // null: no mathematics
  void paint_content(cairo_t* cr, const OverlayPanel& panel, double x, double y, double scale, const Size& size);

  std::map<std::string, SvgRaster> rasters_;  // by SVG key and pixel size
};

}  // namespace impulse::render
