// The overlay's plots and typeset panels (overlay_cairo.h).
#include "render/overlay_cairo.h"

#include "render/cairo_shapes.h"

#include <cstdio>

namespace impulse::render {


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

}  // namespace impulse::render
