// The overlay's text parts (overlay_cairo.h): the title, the clock, captions, the legend, pane
// names and labels, each measured in its forms with the places it would like, and painted where
// the layout put it. Lengths are pixels at 720 lines, times the painter's scale and the form's k.
#include "render/overlay_cairo.h"

#include "render/cairo_shapes.h"

#include <algorithm>
#include <cstdio>

namespace impulse::render {
namespace {

constexpr double kRightColumn = 330;  // the clock's and the plots' column: a title wraps short of it
constexpr double kTitleSize = 24, kTitlePad = 12;
constexpr double kClockSize = 22, kPlaybackSize = 16, kClockPad = 10;
constexpr double kCaptionSize = 24, kCaptionPadX = 18, kCaptionPadY = 10, kCaptionMargin = 28;
constexpr double kLegendSize = 14, kLegendLine = 21, kLegendPad = 10;
constexpr double kLabelSize = 17;

// What a part's forms are: at full size, wrapped narrower, at 0.8 of the size.
struct Shrink {
  double k, wrap_share;
};
constexpr Shrink kTextForms[] = {{1.0, 1.0}, {1.0, 0.6}, {0.8, 1.0}};
constexpr double kBoxForms[] = {1.0, 0.8};

}  // namespace

const WrappedText& OverlayPainter::Cairo::wrapped(const std::string& text, double size, bool bold, double max_width) {
  char font[64];
  std::snprintf(font, sizeof font, "%.3f %d %.3f|", size, int(bold), max_width);
  const auto [found, added] = wrap_cache.try_emplace(font + text);
  WrappedText& wrapped = found->second;
  if (added) {
    cairo_t* cr = context.get();
    set_font(cr, size, bold);
    wrapped.lines = wrap(cr, text, max_width);
    for (const std::string& line : wrapped.lines) wrapped.width = std::max(wrapped.width, text_width(cr, line));
  }
  return wrapped;
}

void OverlayPainter::Cairo::add_title(const Overlay& overlay) {
  if (overlay.title.empty()) return;
  const double column = std::max(width - 2 * margin() - kRightColumn * scale, 60 * scale);
  auto [part, request] = add_part(PartKind::title, 0);
  for (const Shrink& shrink : kTextForms) {
    const double size = kTitleSize * scale * shrink.k, pad = kTitlePad * scale * shrink.k;
    const WrappedText& text = wrapped(overlay.title, size, true, column * shrink.wrap_share);
    part.forms.push_back({shrink.k, &text});
    request.sizes.emplace_back(text.width + 2 * pad, size * 1.2 * text.lines.size() + 2 * pad);
  }
  request.spots = {{Vec2f(margin(), margin()), Vec2f(0, 0)}};
  request.slide = {3, 1};
}

void OverlayPainter::Cairo::draw_title(const Overlay&, const PartForm& form, const ScreenBox& box) {
  cairo_t* cr = context.get();
  const double size = kTitleSize * scale * form.k, pad = kTitlePad * scale * form.k, line_height = size * 1.2;
  panel_box(cr, box.x, box.y, box.w, box.h, 8 * scale * form.k, 0.8);
  set_font(cr, size, true);
  set_colour(cr, kInk);
  for (size_t i = 0; i < form.text->lines.size(); ++i) {
    cairo_move_to(cr, box.x + pad, box.y + pad + line_height * i + size * 0.9);
    show_text(cr, form.text->lines[i]);
  }
}

// Top right: the simulated time, and under it the playback speed.
void OverlayPainter::Cairo::add_clock(const Overlay& overlay) {
  if (overlay.clock.empty() && overlay.playback.empty()) return;
  cairo_t* cr = context.get();
  auto [part, request] = add_part(PartKind::clock, 0);
  // Measured once: every length of a smaller form is k times as long.
  const double clock_size = kClockSize * scale, playback_size = kPlaybackSize * scale, pad = kClockPad * scale;
  set_font(cr, clock_size, true, true);
  double content_width = overlay.clock.empty() ? 0 : text_width(cr, overlay.clock);
  set_font(cr, playback_size, overlay.playback_highlight);
  content_width = std::max(content_width, overlay.playback.empty() ? 0 : text_width(cr, overlay.playback));
  const double content_height =
      (overlay.clock.empty() ? 0 : clock_size * 1.1) + (overlay.playback.empty() ? 0 : playback_size * 1.5);
  for (const double k : kBoxForms) {
    part.forms.push_back({k, nullptr});
    request.sizes.emplace_back(k * (content_width + 2 * pad), k * (content_height + 2 * pad));
  }
  request.spots = {{Vec2f(width - margin(), margin()), Vec2f(1, 0)}};
  request.slide = {3, 1};
}

void OverlayPainter::Cairo::draw_clock(const Overlay& overlay, const PartForm& form, const ScreenBox& box) {
  cairo_t* cr = context.get();
  const double clock_size = kClockSize * scale * form.k, playback_size = kPlaybackSize * scale * form.k;
  const double pad = kClockPad * scale * form.k, right = box.right() - pad;
  panel_box(cr, box.x, box.y, box.w, box.h, 8 * scale * form.k, 0.8);
  double y = box.y + pad;
  if (!overlay.clock.empty()) {
    set_font(cr, clock_size, true, true);
    set_colour(cr, kInk);
    cairo_move_to(cr, right - text_width(cr, overlay.clock), y + clock_size * 0.85);
    show_text(cr, overlay.clock);
    y += clock_size * 1.1;
  }
  if (!overlay.playback.empty()) {
    set_font(cr, playback_size, overlay.playback_highlight);
    set_colour(cr, overlay.playback_highlight ? kHighlight : kMutedInk);
    cairo_move_to(cr, right - text_width(cr, overlay.playback), y + playback_size * 1.2);
    show_text(cr, overlay.playback);
  }
}

// Bottom centre (or centred in the captions' span), the last caption lowest: laid out from the
// last up, each going above the ones below it. A pane's own caption: top centre inside its pane,
// the first highest.
void OverlayPainter::Cairo::add_captions(const Overlay& overlay) {
  const bool span = overlay.captions_right > overlay.captions_left;
  const double left = span ? overlay.captions_left : 0.0, span_width = span ? overlay.captions_right - left : width;
  const double centre = left + span_width / 2;
  auto in_pane = [&](const Caption& caption) { return caption.pane >= 0 && caption.pane < int(overlay.panes.size()); };
  auto add = [&](int i) {
    const Caption& caption = overlay.captions[i];
    if (!(caption.opacity > 0)) return;
    const ScreenBox* pane = in_pane(caption) ? &overlay.panes[caption.pane].box : nullptr;
    auto [part, request] = add_part(PartKind::caption, i);
    for (const Shrink& shrink : kTextForms) {
      const double size = kCaptionSize * scale * shrink.k, pad_x = kCaptionPadX * scale * shrink.k;
      const double pad_y = kCaptionPadY * scale * shrink.k;
      const double wrap_width = (pane ? 0.9 * pane->w - 2 * pad_x : span ? span_width - 2 * pad_x : 0.8 * width) * shrink.wrap_share;
      const WrappedText& text = wrapped(caption.text, size, false, wrap_width);
      part.forms.push_back({shrink.k, &text});
      request.sizes.emplace_back(text.width + 2 * pad_x, size * 1.35 * text.lines.size() + 2 * pad_y);
    }
    if (pane) {
      request.spots = {{Vec2f(pane->x + pane->w / 2, pane->y + kCaptionMargin * scale), Vec2f(0.5f, 0)}};
      request.bounds = *pane;
    } else {
      request.spots = {{Vec2f(centre, height - kCaptionMargin * scale), Vec2f(0.5f, 1)}};
      if (span) request.bounds = {float(left), 0, float(span_width), float(height)};
    }
    request.slide = {3, 1};
  };
  for (int i = 0; i < int(overlay.captions.size()); ++i)
    if (in_pane(overlay.captions[i])) add(i);
  for (int i = int(overlay.captions.size()) - 1; i >= 0; --i)
    if (!in_pane(overlay.captions[i])) add(i);
}

void OverlayPainter::Cairo::draw_caption(const Caption& caption, const PartForm& form, const ScreenBox& box) {
  cairo_t* cr = context.get();
  const double size = kCaptionSize * scale * form.k, line = size * 1.35, pad_y = kCaptionPadY * scale * form.k;
  const double opacity = std::clamp(double(caption.opacity), 0.0, 1.0), centre = box.x + box.w / 2;
  rounded_rectangle(cr, box.x, box.y, box.w, box.h, 10 * scale * form.k);
  cairo_set_source_rgba(cr, 0.08, 0.08, 0.10, 0.78 * opacity);
  cairo_fill(cr);
  set_font(cr, size);
  cairo_set_source_rgba(cr, 1, 1, 1, opacity);
  for (size_t i = 0; i < form.text->lines.size(); ++i) {
    const std::string& text = form.text->lines[i];
    cairo_move_to(cr, centre - text_width(cr, text) / 2, box.y + pad_y + line * i + size * 1.0);
    show_text(cr, text);
  }
}

// At the left, under the title (the top of a frame is mostly sky): what each mark means, and its
// scale. An arrow drawn to scale keeps its length in every form (it is a length on screen).
void OverlayPainter::Cairo::add_legend(const Overlay& overlay) {
  if (overlay.legend.empty()) return;
  cairo_t* cr = context.get();
  auto [part, request] = add_part(PartKind::legend, 0);
  set_font(cr, kLegendSize * scale);
  double text = 0;  // the widest entry's, at full size (a smaller form's is k times as wide)
  for (const LegendEntry& entry : overlay.legend) text = std::max(text, text_width(cr, entry.text));
  for (const double k : kBoxForms) {
    const double pad = kLegendPad * scale * k;
    double icon_width = 34 * scale * k;
    for (const LegendEntry& entry : overlay.legend) icon_width = std::max(icon_width, double(entry.scale_pixels));
    icon_width = std::min(icon_width, 0.2 * width);
    part.forms.push_back({k, nullptr});
    request.sizes.emplace_back(icon_width + 8 * scale * k + k * text + 2 * pad,
                               kLegendLine * scale * k * overlay.legend.size() + 2 * pad);
  }
  request.spots = {{Vec2f(margin(), margin()), Vec2f(0, 0)}};
  request.slide = {3, 1};
  request.under = part_index(PartKind::title, 0);
}

void OverlayPainter::Cairo::draw_legend(const Overlay& overlay, const PartForm& form, const ScreenBox& box) {
  cairo_t* cr = context.get();
  const double k = form.k, size = kLegendSize * scale * k, line = kLegendLine * scale * k, pad = kLegendPad * scale * k;
  double icon_width = 34 * scale * k;
  for (const LegendEntry& entry : overlay.legend) icon_width = std::max(icon_width, double(entry.scale_pixels));
  icon_width = std::min(icon_width, 0.2 * width);
  panel_box(cr, box.x, box.y, box.w, box.h, 8 * scale * k, 0.85);
  set_font(cr, size);
  double row = box.y + pad;
  for (const LegendEntry& entry : overlay.legend) {
    const double middle = row + line / 2;
    if (entry.dot) {
      set_colour(cr, entry.colour);
      cairo_arc(cr, box.x + pad + 6 * scale * k, middle, 4 * scale * k, 0, 2 * M_PI);
      cairo_fill(cr);
    } else if (entry.asleep) {
      sleeping_swatch(cr, box.x + pad, middle - 0.4 * line, 28 * scale * k, 0.8 * line, scale * k, entry.colour);
    } else {
      const double length = entry.scale_pixels > 0 ? std::min(double(entry.scale_pixels), icon_width) : 28 * scale * k;
      legend_arrow(cr, box.x + pad, middle, length, scale * k, entry.colour);
    }
    set_colour(cr, kInk);
    cairo_move_to(cr, box.x + pad + icon_width + 8 * scale * k, middle + size * 0.35);
    show_text(cr, entry.text);
    row += line;
  }
}

// Each pane's name inside it, bottom left, else at another of its corners.
void OverlayPainter::Cairo::add_pane_labels(const Overlay& overlay) {
  cairo_t* cr = context.get();
  const double size = kLabelSize * scale, inset = 8 * scale;
  set_font(cr, size, true);
  for (size_t i = 0; i < overlay.panes.size(); ++i) {
    const OverlayPane& pane = overlay.panes[i];
    if (pane.label.empty()) continue;
    auto [part, request] = add_part(PartKind::pane_label, int(i));
    part.forms.push_back({1.0, nullptr});
    request.sizes.emplace_back(text_width(cr, pane.label), 1.3 * size);
    const ScreenBox& p = pane.box;
    const float left = float(p.x + inset), right = float(p.right() - inset);
    const float top = float(p.y + inset), bottom = float(p.bottom() - inset);
    request.spots = {{Vec2f(left, bottom), Vec2f(0, 1)}, {Vec2f(right, bottom), Vec2f(1, 1)},
                     {Vec2f(left, top), Vec2f(0, 0)}, {Vec2f(right, top), Vec2f(1, 0)}};
    request.bounds = p;
  }
}

// Beside its anchor: right above, right below, left above, left below, above, below (each
// inside the frame); else the free place nearest, within a few lines of the anchor.
void OverlayPainter::Cairo::add_labels(const Overlay& overlay) {
  cairo_t* cr = context.get();
  const double size = kLabelSize * scale, side = 10 * scale, rise = 8 * scale, reach = 200 * scale;
  set_font(cr, size, true);
  for (size_t i = 0; i < overlay.labels.size(); ++i) {
    const OverlayLabel& label = overlay.labels[i];
    auto [part, request] = add_part(PartKind::label, int(i));
    part.forms.push_back({1.0, nullptr});
    const double text = text_width(cr, label.text), ax = label.anchor.x(), ay = label.anchor.y();
    request.sizes.emplace_back(text, 1.3 * size);
    const double baselines[6][2] = {{ax + side, ay - rise},         {ax + side, ay + size + rise},
                                    {ax - side - text, ay - rise},  {ax - side - text, ay + size + rise},
                                    {ax - text / 2, ay - 2 * rise}, {ax - text / 2, ay + size + 2 * rise}};
    for (const auto& baseline : baselines)
      request.spots.push_back({Vec2f(float(baseline[0]), float(baseline[1] - size)), Vec2f(0, 0)});
    request.bounds = {float(ax - reach - text), float(ay - reach), float(2 * (reach + text)), float(2 * reach)};
    const bool in_pane = label.pane >= 0 && label.pane < int(overlay.panes.size());
    const ScreenBox area = in_pane ? overlay.panes[label.pane].box : inner_frame(1 + 3 * scale);
    const float x = std::max(request.bounds.x, area.x), y = std::max(request.bounds.y, area.y);
    request.bounds = {x, y, std::max(0.0f, std::min(request.bounds.right(), area.right()) - x),
                      std::max(0.0f, std::min(request.bounds.bottom(), area.bottom()) - y)};
    if (request.bounds.w < text || request.bounds.h < 1.3 * size) request.bounds = area;  // an anchor off screen
    request.avoid = label.avoid;
    request.lasting = false;  // it follows its anchor
  }
}

void OverlayPainter::Cairo::draw_leader(const OverlayLabel& label, int index, const ScreenBox& box) {
  const Vec2f anchor = label.anchor;
  if (!(anchor.x() >= 0 && anchor.y() >= 0 && anchor.x() <= width && anchor.y() <= height)) return;  // its arrow is off screen
  const Vec2f nearest(std::clamp(anchor.x(), box.x, box.right()), std::clamp(anchor.y(), box.y, box.bottom()));
  const Vec2f along = nearest - anchor;
  if (along.norm() <= kLeaderGap * scale) return;
  // It starts a little off the anchor (the arrow's tip stays clear) and ends at the box's edge.
  const Vec2f from = anchor + along.normalized() * float(4 * scale);
  cairo_t* cr = context.get();
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_move_to(cr, from.x(), from.y());
  cairo_line_to(cr, nearest.x(), nearest.y());
  cairo_set_line_width(cr, 4.0 * scale);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
  cairo_stroke_preserve(cr);
  cairo_set_line_width(cr, 1.5 * scale);
  set_colour(cr, {label.colour.r * 0.8f, label.colour.g * 0.8f, label.colour.b * 0.8f});
  cairo_stroke(cr);
  mark(std::min(from.x(), nearest.x()), std::min(from.y(), nearest.y()), std::abs(along.x()), std::abs(along.y()));
  result.leaders.push_back({index, from, nearest});
}

// Bold text with a white halo, its baseline `kLabelSize` under the box's top.
void OverlayPainter::Cairo::draw_label(const std::string& text, const Colour& colour, const PartForm& form,
                                       const ScreenBox& box) {
  cairo_t* cr = context.get();
  const double size = kLabelSize * scale * form.k;
  set_font(cr, size, true);
  cairo_move_to(cr, box.x, box.y + size);
  text_path(cr, text);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, 4.0 * scale);
  cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
  cairo_stroke_preserve(cr);
  set_colour(cr, {colour.r * 0.8f, colour.g * 0.8f, colour.b * 0.8f});
  cairo_fill(cr);
}

}  // namespace impulse::render
