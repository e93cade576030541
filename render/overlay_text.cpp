#include "render/overlay_text.h"

#include "render/overlay_cairo.h"

#include <pango/pangocairo.h>

#include <algorithm>
#include <memory>
#include <unordered_map>

namespace impulse::render {
namespace {

constexpr const char* kFont = "DejaVu Sans";
constexpr const char* kMonoFont = "DejaVu Sans Mono";

struct LayoutDeleter {
  void operator()(PangoLayout* layout) const { g_object_unref(layout); }
};
using LayoutHandle = std::unique_ptr<PangoLayout, LayoutDeleter>;

// `text` as one line set by Pango in the context's current font (family, weight and size).
LayoutHandle pango_line(cairo_t* cr, const std::string& text) {
  LayoutHandle layout(pango_cairo_create_layout(cr));
  cairo_font_face_t* face = cairo_get_font_face(cr);
  cairo_matrix_t matrix;
  cairo_get_font_matrix(cr, &matrix);
  PangoFontDescription* font = pango_font_description_new();
  pango_font_description_set_family(font, cairo_toy_font_face_get_family(face));
  pango_font_description_set_weight(
      font, cairo_toy_font_face_get_weight(face) == CAIRO_FONT_WEIGHT_BOLD ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
  pango_font_description_set_absolute_size(font, matrix.yy * PANGO_SCALE);
  pango_layout_set_font_description(layout.get(), font);
  pango_font_description_free(font);
  pango_layout_set_single_paragraph_mode(layout.get(), true);
  pango_layout_set_text(layout.get(), text.data(), int(text.size()));
  return layout;
}

}  // namespace

void set_font(cairo_t* cr, double size, bool bold, bool mono) {
  cairo_select_font_face(cr, mono ? kMonoFont : kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// Printable ASCII always (DejaVu has it); else the font's glyphs, none the missing glyph (0), the
// answer kept per font and text (a caption is asked about every frame it shows).
bool font_has_every_character(cairo_t* cr, const std::string& text) {
  if (std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c < 0x7f; })) return true;
  cairo_font_face_t* face = cairo_get_font_face(cr);
  const std::string key = std::string(cairo_toy_font_face_get_family(face)) + char('0' + cairo_toy_font_face_get_weight(face)) + text;
  thread_local std::unordered_map<std::string, bool> known;
  if (const auto found = known.find(key); found != known.end()) return found->second;
  cairo_glyph_t* glyphs = nullptr;
  int count = 0;
  bool every = cairo_scaled_font_text_to_glyphs(cairo_get_scaled_font(cr), 0, 0, text.data(), int(text.size()), &glyphs,
                                                &count, nullptr, nullptr, nullptr) == CAIRO_STATUS_SUCCESS;
  for (int i = 0; every && i < count; ++i) every = glyphs[i].index != 0;
  cairo_glyph_free(glyphs);
  if (known.size() > 4096) known.clear();
  known.emplace(key, every);
  return every;
}

double text_width(cairo_t* cr, const std::string& text) {
  if (font_has_every_character(cr, text)) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
  }
  PangoRectangle logical;
  pango_layout_get_extents(pango_line(cr, text).get(), nullptr, &logical);
  return double(logical.width) / PANGO_SCALE;
}

void show_text(cairo_t* cr, const std::string& text) {
  if (font_has_every_character(cr, text)) {
    cairo_show_text(cr, text.c_str());
    return;
  }
  const LayoutHandle layout = pango_line(cr, text);
  pango_cairo_show_layout_line(cr, pango_layout_get_line_readonly(layout.get(), 0));
}

void text_path(cairo_t* cr, const std::string& text) {
  if (font_has_every_character(cr, text)) {
    cairo_text_path(cr, text.c_str());
    return;
  }
  const LayoutHandle layout = pango_line(cr, text);
  pango_cairo_layout_line_path(cr, pango_layout_get_line_readonly(layout.get(), 0));
}

void set_colour(cairo_t* cr, const Colour& colour, double alpha) {
  cairo_set_source_rgba(cr, colour.r, colour.g, colour.b, alpha);
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

void sleeping_swatch(cairo_t* cr, double x, double y, double w, double h, double scale, const Colour& colour) {
  const double grey = 0.2126 * colour.r + 0.7152 * colour.g + 0.0722 * colour.b;
  auto pale = [&](double c) { return (c + 0.45 * (grey - c)) * 0.7 + 0.25; };
  const Colour paled{float(pale(colour.r)), float(pale(colour.g)), float(pale(colour.b))};
  cairo_save(cr);
  cairo_rectangle(cr, x, y, w, h);
  cairo_clip(cr);
  set_colour(cr, paled);
  cairo_paint(cr);
  set_colour(cr, Colour{0.8f * paled.r, 0.8f * paled.g, 0.8f * paled.b});
  cairo_set_line_width(cr, 2 * scale);
  for (double u = -h; u < w; u += 8 * scale) {
    cairo_move_to(cr, x + u, y + h);
    cairo_line_to(cr, x + u + h, y);
  }
  cairo_stroke(cr);
  cairo_restore(cr);
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

}  // namespace impulse::render
