// Shapes the overlay's painters share. Including this needs cairo's headers: link PkgConfig::CAIRO.
#pragma once
#include <cairo.h>

#include <cmath>

namespace impulse::render {

inline void rounded_rectangle(cairo_t* cr, double x, double y, double width, double height, double radius) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, x + width - radius, y + radius, radius, -M_PI / 2, 0);
  cairo_arc(cr, x + width - radius, y + height - radius, radius, 0, M_PI / 2);
  cairo_arc(cr, x + radius, y + height - radius, radius, M_PI / 2, M_PI);
  cairo_arc(cr, x + radius, y + radius, radius, M_PI, 3 * M_PI / 2);
  cairo_close_path(cr);
}

// A white rounded box behind text, `alpha` opaque.
inline void panel_box(cairo_t* cr, double x, double y, double width, double height, double radius, double alpha) {
  rounded_rectangle(cr, x, y, width, height, radius);
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, alpha);
  cairo_fill(cr);
}

}  // namespace impulse::render
