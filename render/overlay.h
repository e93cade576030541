// The 2D layer drawn over a frame (with cairo, see overlay_painter.h), as plain data: title,
// caption lines, labels beside arrows, the clock and playback speed, a legend and live plots.
// Positions are pixels of the frame, x to the right and y down from its top-left corner.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "render/draw_list.h"

namespace impulse::render {

using Vec2f = Eigen::Vector2f;

// A line on screen, e.g. an arrow drawn under the overlay.
struct ScreenSegment {
  Vec2f from, to;
};

// A rectangle of the frame in pixels, x right and y down from its top-left corner.
struct ScreenBox {
  float x = 0, y = 0, w = 0, h = 0;
  float right() const { return x + w; }
  float bottom() const { return y + h; }
};

// Text beside a point of the frame (e.g. an arrow's tip): "J = 2.41 N·s". It goes to the first
// free place around the anchor (right, then left, above, below) that covers none of `avoid`,
// else to the nearest free place (overlay_layout.h).
struct OverlayLabel {
  Vec2f anchor;
  std::string text;
  Colour colour{0.1f, 0.1f, 0.1f};
  std::vector<ScreenSegment> avoid;
  int pane = -1;  // >= 0: it stays inside that pane (Overlay::panes)
};

// Typeset mathematics: an SVG of filled paths (LaTeX through dvisvgm), drawn in the ink colour.
struct OverlayMath {
  std::string key;                         // one per distinct SVG: the painter rasterises each key once
  std::shared_ptr<const std::string> svg;  // null: none
  std::string tex;                         // what it was typeset from (for tests; not drawn)
  float pixels_per_point = 1.5f;           // the SVG's units (TeX points) on screen at 720 lines
};

// Where a panel goes: at `corner`, or stacked by the painter in a corner of the frame, clear of
// the title and legend (top left), the clock and plots (top right) and the captions (bottom).
enum class PanelPlace { at_corner, top_left, top_right, bottom_left, bottom_right, bottom };

// A box of lines of text and typeset mathematics, e.g. an equation with numbers in it; the first
// line is its heading, the mathematics goes under the lines.
struct OverlayPanel {
  PanelPlace place = PanelPlace::at_corner;
  Vec2f corner = Vec2f::Zero();     // with at_corner: where the box's `align` point goes
  Vec2f align = Vec2f::Zero();      // that point as fractions of the box: (0, 0) its top left, (1, 0) top right
  std::vector<std::string> lines;
  OverlayMath math;
  Colour colour{0.1f, 0.1f, 0.1f};  // of the heading
  float opacity = 1.0f;             // fades in and out like captions
  int pane = -1;                    // >= 0: it stays inside that pane (Overlay::panes)
};

// One line of the legend: a short arrow (or dot) in `colour`, then `text`. When
// `scale_pixels` > 0 the arrow is that long, e.g. what 1 N·s is on screen.
struct LegendEntry {
  Colour colour;
  std::string text;
  float scale_pixels = 0.0f;
  bool dot = false;     // a dot instead of an arrow (contact points)
  bool asleep = false;  // a swatch of `colour` drawn as a sleeping body is: pale and hatched
};

// One curve of a plot: (time s, value) points in time order, drawn in `colour`.
struct PlotSeries {
  Colour colour;
  std::vector<Vec2f> points;
};

// A small line plot that grows as the video plays: x is simulated time from `x_start` to `x_end`.
// The y range is fixed when y_max > y_min (a plot that keeps its scale reads best), else it
// follows the points. Several series share the axes (a comparison: one per variant, in its
// colour); the heading ends with each series' latest value, in its colour.
struct Plot {
  std::string title;   // e.g. "kinetic energy"
  std::string unit;    // e.g. "J"
  float x_end = 1.0f;  // s: the right edge, so the curves grow towards it
  float x_start = 0.0f;  // s: the left edge
  float y_min = 0.0f;
  float y_max = 0.0f;
  std::vector<PlotSeries> series;
};

// A caption line; `opacity` in [0, 1] lets it fade in and out at the ends of its time cue. A
// pane's own (`pane`, an index into Overlay::panes) goes inside that pane, at its top; the others
// under everything, at the bottom.
struct Caption {
  std::string text;
  float opacity = 1.0f;
  int pane = -1;
};

// One pane of a comparison: where it is in the frame, and its name (drawn inside it, bottom left
// where free, in its colour).
struct OverlayPane {
  ScreenBox box;
  std::string label;
  Colour colour;
};

// Where a body is on screen (its projected bounding box): the overlay covers a moving body only
// where no free place is left, and a still one (a ramp, a table) rather than move far.
struct OverlayBody {
  int pane = 0;
  std::string name;
  ScreenBox box;
  bool moving = true;
};

struct Overlay {
  std::string title;                  // top left
  std::vector<Caption> captions;      // lines shown now, bottom centre
  float captions_left = 0.0f;         // captions_right > captions_left: centred between these x
  float captions_right = 0.0f;        // instead (a comparison's empty cell)
  std::vector<OverlayLabel> labels;
  std::vector<OverlayPanel> panels;
  std::string clock;                  // top right, e.g. "t = 1.25 s"
  std::string playback;               // under the clock, e.g. "slow motion ×0.25"; empty: none
  bool playback_highlight = false;    // draw `playback` in bold vermillion (slow motion is on)
  std::vector<LegendEntry> legend;    // under the title
  std::vector<Plot> plots;            // a column at the right, or a row (plots_row_top)
  float plots_row_top = -1.0f;        // >= 0: the plots in a centred row from this y down instead
  std::vector<OverlayPane> panes;     // a comparison's; empty: the scene fills the frame
  std::vector<OverlayBody> bodies;    // what the elements go round
  std::vector<ScreenBox> body_paths;  // where moving bodies go over the whole video (boxes of a coarse
                                      // grid's cells): what stays on screen keeps off them

  bool empty() const {
    return title.empty() && captions.empty() && labels.empty() && panels.empty() && clock.empty() && playback.empty() &&
           legend.empty() && plots.empty() && panes.empty();
  }
};

// A value as labels and plots write it: three significant figures without an exponent (2.41,
// 24.1, 241).
std::string three_figures(double value);

}  // namespace impulse::render
