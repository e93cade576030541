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

std::pair<OverlayPart&, LayoutRequest&> OverlayPainter::Cairo::add_part(PartKind kind, int index) {
  OverlayPart& part = parts.emplace_back();
  part.kind = kind;
  part.index = index;
  LayoutRequest& request = requests.emplace_back();
  request.bounds = inner_frame(margin() / 2);
  request.key = int(kind) * 4096 + index;
  return {part, request};
}

int OverlayPainter::Cairo::part_index(PartKind kind, int index) const {
  for (size_t i = 0; i < parts.size(); ++i)
    if (parts[i].kind == kind && parts[i].index == index) return int(i);
  return -1;
}

ScreenBox OverlayPainter::Cairo::inner_frame(double edge) const {
  return {float(edge), float(edge), float(width - 2 * edge), float(height - 2 * edge)};
}

std::string part_name(const OverlayPart& part) {
  const std::string number = std::to_string(part.index + 1);
  switch (part.kind) {
    case PartKind::title: return "title";
    case PartKind::clock: return "clock";
    case PartKind::caption: return "caption " + number;
    case PartKind::pane_label: return "pane label " + number;
    case PartKind::legend: return "legend";
    case PartKind::plot: return "plot " + number;
    case PartKind::panel: return "panel " + number;
    case PartKind::label: return "label " + number;
  }
  return "element";
}

// In the order of what matters most where: the title and clock in their corners, the captions
// (read now) at the bottom, each pane's name, then what stays put for long (plots, which a
// comparison leaves room for, the legend, equation panels), and last the labels, which follow
// their arrows from frame to frame.
void OverlayPainter::Cairo::lay_out(const Overlay& overlay) {
  parts.clear();
  requests.clear();
  if (wrap_cache.size() > 256) wrap_cache.clear();
  add_title(overlay);
  add_clock(overlay);
  add_captions(overlay);
  add_pane_labels(overlay);
  add_plots(overlay);
  add_legend(overlay);
  add_panels(overlay);
  add_labels(overlay);
  ground.width = width;
  ground.height = height;
  ground.gap = float(std::max(2.0, 8 * scale));
  ground.moving.clear();
  ground.still.clear();
  ground.panes.clear();
  ground.paths = overlay.body_paths;
  for (const OverlayBody& body : overlay.bodies) (body.moving ? ground.moving : ground.still).push_back(body.box);
  for (const OverlayPane& pane : overlay.panes) ground.panes.push_back(pane.box);
}

void OverlayPainter::Cairo::draw(const Overlay& overlay, const OverlayPart& part, const PartForm& form, const ScreenBox& box) {
  switch (part.kind) {
    case PartKind::title: draw_title(overlay, form, box); break;
    case PartKind::clock: draw_clock(overlay, form, box); break;
    case PartKind::caption: draw_caption(overlay.captions[part.index], form, box); break;
    case PartKind::pane_label: {
      const OverlayPane& pane = overlay.panes[part.index];
      draw_label(pane.label, pane.colour, form, box);
      break;
    }
    case PartKind::legend: draw_legend(overlay, form, box); break;
    case PartKind::plot: draw_plot(overlay.plots[part.index], form, box); break;
    case PartKind::panel: panel_painter.paint(context.get(), overlay.panels[part.index], box.x, box.y, scale * form.k); break;
    case PartKind::label: {
      const OverlayLabel& label = overlay.labels[part.index];
      draw_label(label.text, label.colour, form, box);
      break;
    }
  }
  mark(box.x, box.y, box.w, box.h);
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

// out = overlay + frame * (1 - overlay alpha), alpha too (over an opaque frame it stays 255; a
// transparent frame is premultiplied, as cairo's ARGB32 is), native-endian
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
        out[3] = static_cast<uint8_t>(alpha + (out[3] * keep + 127) / 255);
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
  c.result.elements.clear();
  c.result.dropped.clear();
  c.result.leaders.clear();
  if (overlay.empty()) return;

  c.lay_out(overlay);
  const std::vector<Placement>& placements = c.layout.place(c.ground, c.requests);
  for (size_t i = 0; i < c.parts.size(); ++i)  // the leaders first, under everything
    if (c.parts[i].kind == PartKind::label && placements[i].size >= 0)
      c.draw_leader(overlay.labels[c.parts[i].index], c.parts[i].index, placements[i].box);
  for (size_t i = 0; i < c.parts.size(); ++i) {
    const OverlayPart& part = c.parts[i];
    if (placements[i].size < 0) {
      c.result.dropped.push_back(part_name(part));
      continue;
    }
    c.draw(overlay, part, part.forms[placements[i].size], placements[i].box);
    c.result.elements.push_back({part_name(part), placements[i].box});
  }
  if (cairo_status(c.context.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("overlay: cairo failed: ") + cairo_status_to_string(cairo_status(c.context.get())));
  }
  c.composite_onto(frame);
}

const PaintedLayout& OverlayPainter::layout() const { return cairo_->result; }

std::string three_figures(double value) {
  char text[32];
  const double magnitude = std::abs(value);
  std::snprintf(text, sizeof text, magnitude >= 100 ? "%.0f" : magnitude >= 10 ? "%.1f" : "%.2f", value);
  return text;
}

}  // namespace impulse::render
