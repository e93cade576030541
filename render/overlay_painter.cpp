#include "render/overlay_painter.h"

#include "render/overlay_cairo.h"

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
