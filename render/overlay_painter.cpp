#include "render/overlay_painter.h"

#include "render/palette.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/cairo_handles.h"
#include "render/cairo_shapes.h"
#include "render/panel_painter.h"

namespace impulse::render {
namespace {

constexpr const char* kFont = "DejaVu Sans";
constexpr const char* kMonoFont = "DejaVu Sans Mono";
const Colour kInk{0.13f, 0.13f, 0.15f};
const Colour kMutedInk{0.35f, 0.36f, 0.40f};
const Colour kHighlight = okabe_ito::vermillion;  // as the contact normals

void set_colour(cairo_t* cr, const Colour& colour, double alpha = 1.0) {
  cairo_set_source_rgba(cr, colour.r, colour.g, colour.b, alpha);
}

void set_font(cairo_t* cr, double size, bool bold = false, bool mono = false) {
  cairo_select_font_face(cr, mono ? kMonoFont : kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

// A flat arrow from (x0, y) to (x0 + length, y), as the 3D arrows are drawn.
void legend_arrow(cairo_t* cr, double x0, double y, double length, double scale, const Colour& colour) {
  const double head_length = std::min(10.0 * scale, 0.5 * length);
  const double head_half = 5.0 * scale;
  const double shaft_half = 1.5 * scale;
  set_colour(cr, colour);
  cairo_rectangle(cr, x0, y - shaft_half, length - head_length, 2 * shaft_half);
  cairo_fill(cr);
  cairo_move_to(cr, x0 + length - head_length, y - head_half);
  cairo_line_to(cr, x0 + length, y);
  cairo_line_to(cr, x0 + length - head_length, y + head_half);
  cairo_close_path(cr);
  cairo_fill(cr);
}

// Whether the segment from a to b meets the rectangle [x0, x1] x [y0, y1] (Liang-Barsky clipping).
bool segment_meets(const Vec2f& a, const Vec2f& b, double x0, double y0, double x1, double y1) {
  double enter = 0, leave = 1;
  const double d[2] = {double(b.x() - a.x()), double(b.y() - a.y())};
  const double p[4] = {-d[0], d[0], -d[1], d[1]};
  const double q[4] = {a.x() - x0, x1 - a.x(), a.y() - y0, y1 - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) enter = std::max(enter, t);
    else leave = std::min(leave, t);
    if (enter > leave) return false;
  }
  return true;
}

// Splits a word wider than `max_width` between characters (UTF-8 sequences kept whole) into
// pieces that fit, each at least one character.
std::vector<std::string> split_word(cairo_t* cr, const std::string& word, double max_width) {
  std::vector<std::string> pieces;
  std::string piece;
  for (size_t i = 0; i < word.size();) {
    size_t length = 1;  // the character at i: a lead byte, then its continuation bytes (10xxxxxx)
    while (i + length < word.size() && (static_cast<unsigned char>(word[i + length]) & 0xC0) == 0x80) ++length;
    const std::string character = word.substr(i, length);
    if (!piece.empty() && text_width(cr, piece + character) > max_width) {
      pieces.push_back(piece);
      piece.clear();
    }
    piece += character;
    i += length;
  }
  if (!piece.empty()) pieces.push_back(piece);
  return pieces;
}

// Splits `text` at spaces into lines no wider than `max_width`; a word wider than that alone is
// split between characters.
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double max_width) {
  std::vector<std::string> lines;
  std::string line;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    std::vector<std::string> words{text.substr(start, end - start)};
    if (text_width(cr, words.front()) > max_width) words = split_word(cr, words.front(), max_width);
    for (const std::string& word : words) {
      const std::string candidate = line.empty() ? word : line + " " + word;
      if (!line.empty() && text_width(cr, candidate) > max_width) {
        lines.push_back(line);
        line = word;
      } else {
        line = candidate;
      }
    }
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

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

void OverlayPainter::Cairo::title(const Overlay& overlay, double& bottom) {
  const double margin = 20 * scale, pad = 12 * scale, size = 24 * scale;
  bottom = margin;
  if (overlay.title.empty()) return;
  cairo_t* cr = context.get();
  set_font(cr, size, true);
  const double width_available = width - 2 * margin - 330 * scale;  // the right column keeps the rest
  const std::vector<std::string> lines = wrap(cr, overlay.title, width_available);
  double content_width = 0;
  for (const std::string& line : lines) content_width = std::max(content_width, text_width(cr, line));
  const double line_height = size * 1.2;
  const double content_height = line_height * lines.size();
  panel_box(cr, margin, margin, content_width + 2 * pad, content_height + 2 * pad, 8 * scale, 0.8);
  mark(margin, margin, content_width + 2 * pad, content_height + 2 * pad);
  set_colour(cr, kInk);
  for (size_t i = 0; i < lines.size(); ++i) {
    cairo_move_to(cr, margin + pad, margin + pad + line_height * i + size * 0.9);
    cairo_show_text(cr, lines[i].c_str());
  }
  bottom = margin + content_height + 2 * pad;
}

// At the left, under the title (the top of a frame is mostly sky): what each mark means, and
// its scale.
double OverlayPainter::Cairo::legend(const Overlay& overlay, double top) {
  if (overlay.legend.empty()) return top;
  cairo_t* cr = context.get();
  const double margin = 20 * scale, gap = 10 * scale, pad = 10 * scale;
  const double size = 14 * scale, line = 21 * scale;
  double icon_width = 34 * scale;
  for (const LegendEntry& entry : overlay.legend) icon_width = std::max(icon_width, double(entry.scale_pixels));
  icon_width = std::min(icon_width, 0.2 * width);
  set_font(cr, size);
  double content_width = 0;
  for (const LegendEntry& entry : overlay.legend)
    content_width = std::max(content_width, icon_width + 8 * scale + text_width(cr, entry.text));
  const double content_height = line * overlay.legend.size();
  const double x = margin, y = top + gap;
  if (y + content_height + 2 * pad > height - margin) return top;  // no room left
  panel_box(cr, x, y, content_width + 2 * pad, content_height + 2 * pad, 8 * scale, 0.85);
  mark(x, y, content_width + 2 * pad, content_height + 2 * pad);
  double row = y + pad;
  for (const LegendEntry& entry : overlay.legend) {
    const double middle = row + line / 2;
    if (entry.dot) {
      set_colour(cr, entry.colour);
      cairo_arc(cr, x + pad + 6 * scale, middle, 4 * scale, 0, 2 * M_PI);
      cairo_fill(cr);
    } else {
      const double length = entry.scale_pixels > 0 ? std::min(double(entry.scale_pixels), icon_width) : 28 * scale;
      legend_arrow(cr, x + pad, middle, length, scale, entry.colour);
    }
    set_colour(cr, kInk);
    cairo_move_to(cr, x + pad + icon_width + 8 * scale, middle + size * 0.35);
    cairo_show_text(cr, entry.text.c_str());
    row += line;
  }
  return y + content_height + 2 * pad;
}

void OverlayPainter::Cairo::clock(const Overlay& overlay, double& bottom) {
  cairo_t* cr = context.get();
  const double margin = 20 * scale, pad = 10 * scale;
  const double clock_size = 22 * scale, playback_size = 16 * scale;
  bottom = margin;
  if (overlay.clock.empty() && overlay.playback.empty()) return;
  set_font(cr, clock_size, true, true);
  double content_width = overlay.clock.empty() ? 0 : text_width(cr, overlay.clock);
  set_font(cr, playback_size, overlay.playback_highlight);
  content_width = std::max(content_width, overlay.playback.empty() ? 0 : text_width(cr, overlay.playback));
  const double content_height =
      (overlay.clock.empty() ? 0 : clock_size * 1.1) + (overlay.playback.empty() ? 0 : playback_size * 1.5);
  const double right = width - margin;
  panel_box(cr, right - content_width - 2 * pad, margin, content_width + 2 * pad, content_height + 2 * pad, 8 * scale, 0.8);
  mark(right - content_width - 2 * pad, margin, content_width + 2 * pad, content_height + 2 * pad);
  double y = margin + pad;
  if (!overlay.clock.empty()) {
    set_font(cr, clock_size, true, true);
    set_colour(cr, kInk);
    cairo_move_to(cr, right - pad - text_width(cr, overlay.clock), y + clock_size * 0.85);
    cairo_show_text(cr, overlay.clock.c_str());
    y += clock_size * 1.1;
  }
  if (!overlay.playback.empty()) {
    set_font(cr, playback_size, overlay.playback_highlight);
    set_colour(cr, overlay.playback_highlight ? kHighlight : kMutedInk);
    cairo_move_to(cr, right - pad - text_width(cr, overlay.playback), y + playback_size * 1.2);
    cairo_show_text(cr, overlay.playback.c_str());
  }
  bottom = margin + content_height + 2 * pad;
}

double OverlayPainter::Cairo::plots(const Overlay& overlay, double top) {
  cairo_t* cr = context.get();
  const double margin = 20 * scale, gap = 10 * scale;
  const double plot_height = 88 * scale, pad = 9 * scale;
  const double title_size = 13 * scale;
  const bool row = overlay.plots_row_top >= 0;
  // A row shares the frame's width, each plot between 270 and 380 (at 720 lines) wide.
  const double share = (width - 2 * margin - (double(overlay.plots.size()) - 1) * gap) / std::max<size_t>(overlay.plots.size(), 1);
  const double plot_width = row ? std::clamp(share, 270 * scale, 380 * scale) : 270 * scale;
  const double row_width = overlay.plots.size() * (plot_width + gap) - gap;
  double x = row ? std::max(margin, (width - row_width) / 2) : width - margin - plot_width;
  double y = row ? overlay.plots_row_top : top + gap;
  double bottom = top;  // of the column
  for (const Plot& plot : overlay.plots) {
    if (y + plot_height > height - margin || x + plot_width > width) break;  // no room left
    panel_box(cr, x, y, plot_width, plot_height, 8 * scale, 0.85);
    mark(x, y, plot_width, plot_height);

    // The latest values, right-aligned, the last series rightmost (the unit is in the heading,
    // unless the values leave it no room).
    set_font(cr, title_size, true, true);
    double values_width = 0;
    for (const PlotSeries& series : plot.series)
      if (!series.points.empty()) values_width += text_width(cr, three_figures(series.points.back().y())) + 0.6 * title_size;
    set_font(cr, title_size, true);
    std::string heading = plot.unit.empty() ? plot.title : plot.title + " (" + plot.unit + ")";
    if (text_width(cr, heading) + values_width > plot_width - 2 * pad) heading = plot.title;
    set_colour(cr, kInk);
    cairo_move_to(cr, x + pad, y + pad + title_size * 0.8);
    cairo_show_text(cr, heading.c_str());
    set_font(cr, title_size, true, true);
    double value_right = x + plot_width - pad;
    for (auto series = plot.series.rbegin(); series != plot.series.rend(); ++series) {
      if (series->points.empty()) continue;
      const std::string value = three_figures(series->points.back().y());
      value_right -= text_width(cr, value);
      set_colour(cr, series->colour);
      cairo_move_to(cr, value_right, y + pad + title_size * 0.8);
      cairo_show_text(cr, value.c_str());
      value_right -= 0.6 * title_size;
    }

    const double left = x + pad, right = x + plot_width - pad;
    const double area_top = y + pad + title_size * 1.4, area_bottom = y + plot_height - pad;
    double y_min = plot.y_min, y_max = plot.y_max;
    if (!(y_max > y_min)) {
      y_min = 0;
      y_max = 0;
      for (const PlotSeries& series : plot.series)
        for (const Vec2f& p : series.points) {
          y_min = std::min(y_min, double(p.y()));
          y_max = std::max(y_max, double(p.y()));
        }
      if (!(y_max > y_min)) y_max = y_min + 1;
      y_max += 0.1 * (y_max - y_min);
    }
    const double x_start = plot.x_start, x_end = plot.x_end > x_start ? plot.x_end : x_start + 1.0;
    auto to_x = [&](double t) { return left + (right - left) * std::clamp((t - x_start) / (x_end - x_start), 0.0, 1.0); };
    auto to_y = [&](double v) { return area_bottom - (area_bottom - area_top) * std::clamp((v - y_min) / (y_max - y_min), 0.0, 1.0); };

    // Axes: the time axis at zero (or the bottom), the value axis at x_start.
    cairo_set_line_width(cr, 1.0 * scale);
    set_colour(cr, kMutedInk, 0.6);
    const double zero = to_y(std::clamp(0.0, y_min, y_max));
    cairo_move_to(cr, left, zero);
    cairo_line_to(cr, right, zero);
    cairo_move_to(cr, left, area_top);
    cairo_line_to(cr, left, area_bottom);
    cairo_stroke(cr);

    for (const PlotSeries& series : plot.series) {
      if (series.points.empty()) continue;
      cairo_set_line_width(cr, 2.0 * scale);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      set_colour(cr, series.colour);
      cairo_move_to(cr, to_x(series.points.front().x()), to_y(series.points.front().y()));
      for (const Vec2f& p : series.points) cairo_line_to(cr, to_x(p.x()), to_y(p.y()));
      cairo_stroke(cr);
      cairo_arc(cr, to_x(series.points.back().x()), to_y(series.points.back().y()), 3.5 * scale, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    if (row) {
      x += plot_width + gap;
    } else {
      bottom = y + plot_height;
      y += plot_height + gap;
    }
  }
  return bottom;
}

void OverlayPainter::Cairo::labels(const Overlay& overlay) {
  cairo_t* cr = context.get();
  const double size = 17 * scale;
  set_font(cr, size, true);
  for (const OverlayLabel& label : overlay.labels) {
    const double text = text_width(cr, label.text);
    const auto [x, y] = label_place(label, text, size);
    mark(x, y - size, text, 1.3 * size);
    cairo_move_to(cr, x, y);
    cairo_text_path(cr, label.text.c_str());
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_width(cr, 4.0 * scale);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
    cairo_stroke_preserve(cr);
    set_colour(cr, {label.colour.r * 0.8f, label.colour.g * 0.8f, label.colour.b * 0.8f});
    cairo_fill(cr);
  }
}

// The label's text baseline: the first of six places around its anchor (right above, right below,
// left above, left below, above, below), each kept inside the frame, whose box covers none of the
// segments it avoids; else the one covering fewest.
std::pair<double, double> OverlayPainter::Cairo::label_place(const OverlayLabel& label, double text, double size) const {
  const double ax = label.anchor.x(), ay = label.anchor.y(), side = 10 * scale, rise = 8 * scale;
  const double places[6][2] = {{ax + side, ay - rise},          {ax + side, ay + size + rise},
                               {ax - side - text, ay - rise},   {ax - side - text, ay + size + rise},
                               {ax - text / 2, ay - 2 * rise},  {ax - text / 2, ay + size + 2 * rise}};
  const double margin = 3 * scale;  // an arrow's half width
  std::pair<double, double> best{0, 0};
  int fewest = INT32_MAX;
  for (const auto& place : places) {
    const double x = std::clamp(place[0], 4.0, width - text - 4.0);
    const double y = std::clamp(place[1], size + 4.0, height - 4.0);
    int covered = 0;
    for (const ScreenSegment& segment : label.avoid)
      covered += segment_meets(segment.from, segment.to, x - margin, y - size - margin, x + text + margin, y + 0.3 * size + margin);
    if (covered < fewest) {
      fewest = covered;
      best = {x, y};
    }
    if (covered == 0) break;
  }
  return best;
}

// Each panel at its corner, or stacked in its place: down from under the title and legend (top
// left) or the clock and plots (top right), up from the bottom (above the captions when centred).
void OverlayPainter::Cairo::panels(const Overlay& overlay, double left_top, double right_top, double captions_top) {
  cairo_t* cr = context.get();
  const double margin = 20 * scale, gap = 10 * scale;
  double next_top[2] = {left_top + gap, right_top + gap};              // top left, top right
  // Bottom left, right and centre: above the captions (which may span most of the width).
  const double bottom = std::min(height - margin, captions_top - gap);
  double next_bottom[3] = {bottom, bottom, bottom};
  for (const OverlayPanel& panel : overlay.panels) {
    const PanelPainter::Size size = panel_painter.measure(cr, panel, scale);
    double x = 0, y = 0;
    switch (panel.place) {
      case PanelPlace::at_corner:
        x = panel.corner.x() - panel.align.x() * size.width;
        y = panel.corner.y() - panel.align.y() * size.height;
        break;
      case PanelPlace::top_left:
      case PanelPlace::top_right: {
        const bool right = panel.place == PanelPlace::top_right;
        x = right ? width - margin - size.width : margin;
        y = next_top[right];
        next_top[right] += size.height + gap;
        break;
      }
      case PanelPlace::bottom_left:
      case PanelPlace::bottom_right:
      case PanelPlace::bottom: {
        const int which = panel.place == PanelPlace::bottom_left ? 0 : panel.place == PanelPlace::bottom_right ? 1 : 2;
        x = which == 0 ? margin : which == 1 ? width - margin - size.width : (width - size.width) / 2;
        y = next_bottom[which] - size.height;
        next_bottom[which] = y - gap;
        break;
      }
    }
    x = std::clamp(x, 0.0, std::max(0.0, width - size.width));
    y = std::clamp(y, 0.0, std::max(0.0, height - size.height));
    panel_painter.paint(cr, panel, x, y, scale);
    mark(x, y, size.width, size.height);
  }
}

double OverlayPainter::Cairo::captions(const Overlay& overlay) {
  if (overlay.captions.empty()) return height;
  cairo_t* cr = context.get();
  const double size = 24 * scale, line = size * 1.35, pad_x = 18 * scale, pad_y = 10 * scale;
  const double margin = 28 * scale;
  set_font(cr, size);
  const bool span = overlay.captions_right > overlay.captions_left;
  const double left = span ? overlay.captions_left : 0.0, span_width = span ? overlay.captions_right - left : width;
  const double centre = left + span_width / 2;
  // Bottom up: the last caption sits lowest.
  double bottom = height - margin;
  for (auto caption = overlay.captions.rbegin(); caption != overlay.captions.rend(); ++caption) {
    const std::vector<std::string> lines = wrap(cr, caption->text, span ? span_width - 2 * pad_x : 0.8 * width);
    double box_width = 0;
    for (const std::string& l : lines) box_width = std::max(box_width, text_width(cr, l));
    const double box_height = line * lines.size() + 2 * pad_y;
    const double x = centre - box_width / 2 - pad_x, y = bottom - box_height;
    const double opacity = std::clamp(double(caption->opacity), 0.0, 1.0);
    rounded_rectangle(cr, x, y, box_width + 2 * pad_x, box_height, 10 * scale);
    mark(x, y, box_width + 2 * pad_x, box_height);
    cairo_set_source_rgba(cr, 0.08, 0.08, 0.10, 0.78 * opacity);
    cairo_fill(cr);
    cairo_set_source_rgba(cr, 1, 1, 1, opacity);
    for (size_t i = 0; i < lines.size(); ++i) {
      cairo_move_to(cr, centre - text_width(cr, lines[i]) / 2, y + pad_y + line * i + size * 1.0);
      cairo_show_text(cr, lines[i].c_str());
    }
    bottom = y - 8 * scale;
  }
  return bottom + 8 * scale;
}

void OverlayPainter::Cairo::clear_painted() {
  cairo_surface_flush(surface.get());
  uint8_t* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (const PixelRect& rect : painted)
    for (int y = rect.y0; y < rect.y1; ++y)
      std::memset(data + static_cast<size_t>(y) * stride + 4 * rect.x0, 0, 4 * static_cast<size_t>(rect.x1 - rect.x0));
  cairo_surface_mark_dirty(surface.get());
  painted.clear();
}

// out = overlay + frame * (1 - overlay alpha), cairo's ARGB32 being premultiplied, native-endian
// 32-bit words (B, G, R, A in memory on little-endian machines); the frame is R, G, B, A bytes.
// Each pixel once, even where painted rectangles overlap.
void OverlayPainter::Cairo::composite_onto(Frame& frame) {
  cairo_surface_flush(surface.get());
  const uint8_t* source = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < height; ++y) {
    spans.clear();
    for (const PixelRect& rect : painted)
      if (y >= rect.y0 && y < rect.y1) spans.emplace_back(rect.x0, rect.x1);
    if (spans.empty()) continue;
    std::sort(spans.begin(), spans.end());
    const auto* row = reinterpret_cast<const uint32_t*>(source + static_cast<size_t>(y) * stride);
    uint8_t* target = frame.rgba.data() + static_cast<size_t>(y) * width * 4;
    int done = 0;  // pixels left of this are composited
    for (const auto& [begin, end] : spans) {
      for (int x = std::max(begin, done); x < end; ++x) {
        const uint32_t pixel = row[x];
        const uint32_t alpha = pixel >> 24;
        if (alpha == 0) continue;
        const uint32_t keep = 255 - alpha;
        uint8_t* out = target + 4 * x;
        out[0] = static_cast<uint8_t>(((pixel >> 16) & 255) + (out[0] * keep + 127) / 255);
        out[1] = static_cast<uint8_t>(((pixel >> 8) & 255) + (out[1] * keep + 127) / 255);
        out[2] = static_cast<uint8_t>((pixel & 255) + (out[2] * keep + 127) / 255);
      }
      done = std::max(done, end);
    }
  }
}

OverlayPainter::OverlayPainter(int width, int height) : cairo_(std::make_unique<Cairo>()) {
  Cairo& c = *cairo_;
  c.width = width;
  c.height = height;
  c.scale = height / 720.0;
  c.surface.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  if (cairo_surface_status(c.surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("overlay: cairo cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                             " image: " + cairo_status_to_string(cairo_surface_status(c.surface.get())));
  }
  c.context.reset(cairo_create(c.surface.get()));
  if (cairo_status(c.context.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("overlay: cairo cannot draw: ") + cairo_status_to_string(cairo_status(c.context.get())));
  }
}

OverlayPainter::~OverlayPainter() = default;

void OverlayPainter::paint(const Overlay& overlay, Frame& frame) {
  Cairo& c = *cairo_;
  if (frame.width != c.width || frame.height != c.height) {
    throw std::invalid_argument("overlay: frame is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                " but the painter is " + std::to_string(c.width) + "x" + std::to_string(c.height));
  }
  c.clear_painted();
  if (overlay.empty()) return;

  double title_bottom = 0, clock_bottom = 0;
  c.title(overlay, title_bottom);
  const double legend_bottom = c.legend(overlay, title_bottom);
  c.clock(overlay, clock_bottom);
  const double plots_bottom = c.plots(overlay, clock_bottom);
  c.labels(overlay);
  const double captions_top = c.captions(overlay);
  c.panels(overlay, legend_bottom, overlay.plots_row_top >= 0 ? clock_bottom : plots_bottom, captions_top);
  if (cairo_status(c.context.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("overlay: cairo failed: ") + cairo_status_to_string(cairo_status(c.context.get())));
  }
  c.composite_onto(frame);
}

std::string three_figures(double value) {
  char text[32];
  const double magnitude = std::abs(value);
  std::snprintf(text, sizeof text, magnitude >= 100 ? "%.0f" : magnitude >= 10 ? "%.1f" : "%.2f", value);
  return text;
}

}  // namespace impulse::render
