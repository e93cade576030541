// What the overlay's painting files share (overlay_painter.cpp, overlay_text.cpp,
// overlay_plots.cpp): the cairo surface and context with the parts painted, the fonts and inks,
// and the text and arrow helpers. Inside the renderer only.
#pragma once
#include "render/cairo_handles.h"
#include "render/overlay.h"
#include "render/overlay_painter.h"
#include "render/palette.h"
#include "render/panel_painter.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace impulse::render {

inline constexpr const char* kFont = "DejaVu Sans";
inline constexpr const char* kMonoFont = "DejaVu Sans Mono";
inline const Colour kInk{0.13f, 0.13f, 0.15f};
inline const Colour kMutedInk{0.35f, 0.36f, 0.40f};
inline const Colour kHighlight = okabe_ito::vermillion;  // as the contact normals

void set_colour(cairo_t* cr, const Colour& colour, double alpha = 1.0);
void set_font(cairo_t* cr, double size, bool bold = false, bool mono = false);
double text_width(cairo_t* cr, const std::string& text);
// A flat arrow from (x0, y) to (x0 + length, y), as the 3D arrows are drawn.
void legend_arrow(cairo_t* cr, double x0, double y, double length, double scale, const Colour& colour);
// Whether the segment from a to b meets the rectangle [x0, x1] x [y0, y1] (Liang-Barsky clipping).
bool segment_meets(const Vec2f& a, const Vec2f& b, double x0, double y0, double x1, double y1);
// Splits a word wider than `max_width` between characters (UTF-8 sequences kept whole) into
// pieces that fit, each at least one character.
std::vector<std::string> split_word(cairo_t* cr, const std::string& word, double max_width);
// Splits `text` at spaces into lines no wider than `max_width`; a word wider than that alone is
// split between characters.
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double max_width);

// The parts of the layer painted this time (pixel rectangles): only they are cleared and
// composited, so a frame with a small overlay costs little.
struct PixelRect {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
};

struct OverlayPainter::Cairo {
  int width;
  int height;
  double scale;  // 1 at 720 lines
  cairo::SurfaceHandle surface;
  cairo::ContextHandle context;
  std::vector<PixelRect> painted;
  std::vector<std::pair<int, int>> spans;  // scratch for composite_onto
  PanelPainter panel_painter;              // keeps each typeset SVG rasterised

  void mark(double x, double y, double w, double h) {
    const int margin = 2 + static_cast<int>(4 * scale);  // anti-aliased edges and text halos
    PixelRect rect{std::max(0, static_cast<int>(std::floor(x)) - margin),
                   std::max(0, static_cast<int>(std::floor(y)) - margin),
                   std::min(width, static_cast<int>(std::ceil(x + w)) + margin),
                   std::min(height, static_cast<int>(std::ceil(y + h)) + margin)};
    if (rect.x1 > rect.x0 && rect.y1 > rect.y0) painted.push_back(rect);
  }
  void clear_painted();

  void title(const Overlay& overlay, double& bottom);
  void clock(const Overlay& overlay, double& bottom);
  double plots(const Overlay& overlay, double top);   // returns the column's bottom
  double legend(const Overlay& overlay, double top);  // returns its bottom
  void labels(const Overlay& overlay);
  std::pair<double, double> label_place(const OverlayLabel& label, double text_width, double size) const;
  // `left_top`, `right_top`: where the left and right columns' content ends; `captions_top`.
  void panels(const Overlay& overlay, double left_top, double right_top, double captions_top);
  double captions(const Overlay& overlay);  // returns the top of the captions (height if none)
  void composite_onto(Frame& frame);
};

}  // namespace impulse::render
