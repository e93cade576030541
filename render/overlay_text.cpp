#include "render/overlay_cairo.h"

#include "render/cairo_shapes.h"

namespace impulse::render {

void set_colour(cairo_t* cr, const Colour& colour, double alpha) {
  cairo_set_source_rgba(cr, colour.r, colour.g, colour.b, alpha);
}

void set_font(cairo_t* cr, double size, bool bold, bool mono) {
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
