// What the overlay's painting files share (overlay_painter.cpp, overlay_parts.cpp,
// overlay_plots.cpp, overlay_text.cpp): the cairo surface and context, the parts of a frame's
// overlay as measured, laid out and painted, the fonts and inks, and the text and arrow helpers.
// Inside the renderer only.
#pragma once
#include "render/cairo_handles.h"
#include "render/overlay.h"
#include "render/overlay_layout.h"
#include "render/overlay_painter.h"
#include "render/overlay_text.h"
#include "render/palette.h"
#include "render/panel_painter.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace impulse::render {

inline const Colour kInk{0.13f, 0.13f, 0.15f};
inline const Colour kMutedInk{0.35f, 0.36f, 0.40f};
inline const Colour kHighlight = okabe_ito::vermillion;  // as the contact normals

void set_colour(cairo_t* cr, const Colour& colour, double alpha = 1.0);
// A flat arrow from (x0, y) to (x0 + length, y), as the 3D arrows are drawn.
void legend_arrow(cairo_t* cr, double x0, double y, double length, double scale, const Colour& colour);
// A w x h swatch of `colour` at (x, y) drawn as a sleeping body is (shaders.cpp): paled towards
// its grey, with darker diagonal stripes 8 pixels (times `scale`) apart.
void sleeping_swatch(cairo_t* cr, double x, double y, double w, double h, double scale, const Colour& colour);

// The parts of the layer painted this time (pixel rectangles): only they are cleared and
// composited, so a frame with a small overlay costs little.
struct PixelRect {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
};

// What kind of element a part is; its index says which caption, pane, plot, panel or label.
enum class PartKind { title, clock, caption, pane_label, legend, plot, panel, label };

// Text wrapped to a width in a font, and its widest line's width.
struct WrappedText {
  std::vector<std::string> lines;
  double width = 0;
};

// One way to draw a part: its letters and boxes at `k` times their designed size, its text (a
// title's or caption's) wrapped to a width.
struct PartForm {
  double k = 1;
  const WrappedText* text = nullptr;
};

struct OverlayPart {
  PartKind kind = PartKind::title;
  int index = 0;
  std::vector<PartForm> forms;  // one per size of its layout request, the preferred first
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

  // This frame's parts and their requests, one for one, and where the layout put them.
  std::vector<OverlayPart> parts;
  std::vector<LayoutRequest> requests;
  LayoutGround ground;
  OverlayLayout layout;
  PaintedLayout result;
  // Titles and captions as wrapped, kept from frame to frame (they stay the same for many
  // frames); forgotten, between frames, when many are kept.
  std::unordered_map<std::string, WrappedText> wrap_cache;
  const WrappedText& wrapped(const std::string& text, double size, bool bold, double max_width);

  void mark(double x, double y, double w, double h) {
    const int margin = 2 + static_cast<int>(4 * scale);  // anti-aliased edges and text halos
    PixelRect rect{std::max(0, static_cast<int>(std::floor(x)) - margin),
                   std::max(0, static_cast<int>(std::floor(y)) - margin),
                   std::min(width, static_cast<int>(std::ceil(x + w)) + margin),
                   std::min(height, static_cast<int>(std::ceil(y + h)) + margin)};
    if (rect.x1 > rect.x0 && rect.y1 > rect.y0) painted.push_back(rect);
  }
  void clear_painted();

  // The frame's margin (20 pixels at 720 lines): where elements go, at most half of it from an edge.
  double margin() const { return 20 * scale; }
  ScreenBox inner_frame(double edge) const;  // the frame without `edge` pixels round it
  // A new part and its request, to be filled by the add_ functions.
  std::pair<OverlayPart&, LayoutRequest&> add_part(PartKind kind, int index);
  int part_index(PartKind kind, int index) const;  // of a part added before; -1: none

  // Each measures its part in each of its forms and says where it would go (overlay_parts.cpp,
  // overlay_plots.cpp), in the order the layout places them.
  void add_title(const Overlay& overlay);
  void add_clock(const Overlay& overlay);
  void add_captions(const Overlay& overlay);
  void add_pane_labels(const Overlay& overlay);
  void add_legend(const Overlay& overlay);
  void add_plots(const Overlay& overlay);
  void add_panels(const Overlay& overlay);
  void add_labels(const Overlay& overlay);
  void lay_out(const Overlay& overlay);  // all of the above, then the layout

  // Each paints its part in `form` with its box at `box`.
  void draw(const Overlay& overlay, const OverlayPart& part, const PartForm& form, const ScreenBox& box);
  void draw_title(const Overlay& overlay, const PartForm& form, const ScreenBox& box);
  void draw_clock(const Overlay& overlay, const PartForm& form, const ScreenBox& box);
  void draw_caption(const Caption& caption, const PartForm& form, const ScreenBox& box);
  void draw_label(const std::string& text, const Colour& colour, const PartForm& form, const ScreenBox& box);
  // A line from a label's anchor to its box where the box is further than kLeaderGap from it.
  static constexpr double kLeaderGap = 14;  // pixels at 720 lines: the nearest spots are closer
  void draw_leader(const OverlayLabel& label, int index, const ScreenBox& box);
  void draw_legend(const Overlay& overlay, const PartForm& form, const ScreenBox& box);
  void draw_plot(const Plot& plot, const PartForm& form, const ScreenBox& box);
  void composite_onto(Frame& frame);
};

// The name a part has in the layout report: "title", "caption 2", "pane label 1", ...
std::string part_name(const OverlayPart& part);

}  // namespace impulse::render
