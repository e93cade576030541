// The overlay's plots and typeset panels (overlay_cairo.h).
#include "render/overlay_cairo.h"

#include "render/cairo_shapes.h"

#include <cstdio>

namespace impulse::render {
namespace {

constexpr double kPlotWidth = 270, kPlotHeight = 88, kWidestPlot = 380;  // a row's plots share its width up to this
constexpr double kBoxForms[] = {1.0, 0.8};
constexpr double kPanelForms[] = {1.0, 0.85};

}  // namespace

// A column at the right, under the clock; or a centred row from plots_row_top down (under a
// comparison's panes), each plot then between 270 and 380 wide.
void OverlayPainter::Cairo::add_plots(const Overlay& overlay) {
  const double gap = 10 * scale;
  const bool row = overlay.plots_row_top >= 0;
  const size_t count = overlay.plots.size();
  const double share = (width - 2 * margin() - (double(count) - 1) * gap) / std::max<size_t>(count, 1);
  for (size_t i = 0; i < count; ++i) {
    auto [part, request] = add_part(PartKind::plot, int(i));
    for (const double k : kBoxForms) {
      const double plot_width = (row ? std::clamp(share, kPlotWidth * scale, kWidestPlot * scale) : kPlotWidth * scale) * k;
      part.forms.push_back({k, nullptr});
      request.sizes.emplace_back(plot_width, kPlotHeight * scale * k);
    }
    if (row) {
      const double plot_width = request.sizes.front().x(), row_width = count * (plot_width + gap) - gap;
      const double x = std::max(margin(), (width - row_width) / 2) + i * (plot_width + gap);
      request.spots = {{Vec2f(float(x), overlay.plots_row_top), Vec2f(0, 0)}};
      request.slide = {1, 3};
    } else {  // each under the one before, wherever that went
      request.spots = {{Vec2f(width - margin(), margin()), Vec2f(1, 0)}};
      request.slide = {3, 1};
      if (i > 0) request.under = part_index(PartKind::plot, int(i) - 1);
    }
  }
}

// The plot's heading with the latest values, its axes and its curves, in `box`.
void OverlayPainter::Cairo::draw_plot(const Plot& plot, const PartForm& form, const ScreenBox& box) {
  cairo_t* cr = context.get();
  const double pad = 9 * scale * form.k, title_size = 13 * scale * form.k;
  const double x = box.x, y = box.y, plot_width = box.w, plot_height = box.h;
  panel_box(cr, x, y, plot_width, plot_height, 8 * scale * form.k, 0.85);

  // The latest values, right-aligned, the last series rightmost (the unit is in the heading,
  // unless the values leave it no room).
  set_font(cr, title_size, true, true);
  double values_width = 0;
  for (const PlotSeries& series : plot.series)
    if (!series.points.empty()) values_width += text_width(cr, three_figures(series.points.back().y())) + 0.6 * title_size;
  set_font(cr, title_size, true);
  std::string heading = plot.unit.empty() ? plot.title : plot.title + " (" + plot.unit + ")";
  if (text_width(cr, heading) + values_width > plot_width - 2 * pad) heading = plot.title;
  // A title the values leave no room for is cut short, a whole UTF-8 character at a time.
  const double room = plot_width - 2 * pad - values_width;
  if (text_width(cr, heading) > room) {
    while (!heading.empty() && text_width(cr, heading + "\u2026") > room) {
      while (!heading.empty() && (static_cast<unsigned char>(heading.back()) & 0xC0) == 0x80) heading.pop_back();
      if (!heading.empty()) heading.pop_back();
    }
    if (!heading.empty()) heading += "\u2026";
  }
  set_colour(cr, kInk);
  cairo_move_to(cr, x + pad, y + pad + title_size * 0.8);
  show_text(cr, heading);
  set_font(cr, title_size, true, true);
  double value_right = x + plot_width - pad;
  for (auto series = plot.series.rbegin(); series != plot.series.rend(); ++series) {
    if (series->points.empty()) continue;
    const std::string value = three_figures(series->points.back().y());
    value_right -= text_width(cr, value);
    set_colour(cr, series->colour);
    cairo_move_to(cr, value_right, y + pad + title_size * 0.8);
    show_text(cr, value);
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
    cairo_set_line_width(cr, 2.0 * scale * form.k);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    set_colour(cr, series.colour);
    cairo_move_to(cr, to_x(series.points.front().x()), to_y(series.points.front().y()));
    for (const Vec2f& p : series.points) cairo_line_to(cr, to_x(p.x()), to_y(p.y()));
    cairo_stroke(cr);
    cairo_arc(cr, to_x(series.points.back().x()), to_y(series.points.back().y()), 3.5 * scale * form.k, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

// Each panel in its place in the frame, or in its pane: a named corner (stacked under, or above,
// what is already there by the layout) or its own corner point.
void OverlayPainter::Cairo::add_panels(const Overlay& overlay) {
  cairo_t* cr = context.get();
  for (size_t i = 0; i < overlay.panels.size(); ++i) {
    const OverlayPanel& panel = overlay.panels[i];
    if (!(panel.opacity > 0)) continue;
    auto [part, request] = add_part(PartKind::panel, int(i));
    for (const double k : kPanelForms) {
      const PanelPainter::Size size = panel_painter.measure(cr, panel, scale * k);
      part.forms.push_back({k, nullptr});
      request.sizes.emplace_back(size.width, size.height);
    }
    const bool in_pane = panel.pane >= 0 && panel.pane < int(overlay.panes.size());
    const ScreenBox area = in_pane ? overlay.panes[panel.pane].box : ScreenBox{0, 0, float(width), float(height)};
    const float inset = float(in_pane ? 10 * scale : margin());
    const float left = area.x + inset, right = area.right() - inset, top = area.y + inset, bottom = area.bottom() - inset;
    request.slide = {3, 1};
    switch (panel.place) {
      case PanelPlace::at_corner: request.spots = {{panel.corner, panel.align}}; request.slide = {1, 1}; break;
      case PanelPlace::top_left: request.spots = {{Vec2f(left, top), Vec2f(0, 0)}}; break;
      case PanelPlace::top_right: request.spots = {{Vec2f(right, top), Vec2f(1, 0)}}; break;
      case PanelPlace::bottom_left: request.spots = {{Vec2f(left, bottom), Vec2f(0, 1)}}; break;
      case PanelPlace::bottom_right: request.spots = {{Vec2f(right, bottom), Vec2f(1, 1)}}; break;
      case PanelPlace::bottom: request.spots = {{Vec2f((left + right) / 2, bottom), Vec2f(0.5f, 1)}}; break;
    }
    // In its pane, or under it where the pane is full (the frame's band below a comparison).
    if (in_pane) {
      request.home = panel.pane;
      request.bounds = {area.x, area.y, area.w, std::max(area.h, request.bounds.bottom() - area.y)};
    }
  }
}

}  // namespace impulse::render
