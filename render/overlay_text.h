// Text in the overlay, in the font set_font chose (DejaVu Sans, bold or monospace). Text whose
// characters the font has all of (nearly all: Latin, Greek, the usual mathematical signs) is set
// by cairo itself; any other is set by Pango, which takes each missing character from a font
// that has it through fontconfig's fallback (Noto for the rest of Unicode, Noto Color Emoji for
// emoji), so that nothing is drawn as an empty box where some font on the machine has it.
// Including this needs cairo's headers (link PkgConfig::CAIRO).
#pragma once
#include <cairo.h>

#include <string>
#include <vector>

namespace impulse::render {

void set_font(cairo_t* cr, double size, bool bold = false, bool mono = false);
double text_width(cairo_t* cr, const std::string& text);  // its advance, pixels
void show_text(cairo_t* cr, const std::string& text);     // its baseline from the current point
void text_path(cairo_t* cr, const std::string& text);     // its outline as the current path, as cairo_text_path
// Whether the current font has every character of `text` (so cairo sets it without Pango).
bool font_has_every_character(cairo_t* cr, const std::string& text);

// Splits a word wider than `max_width` between characters (UTF-8 sequences kept whole) into
// pieces that fit, each at least one character.
std::vector<std::string> split_word(cairo_t* cr, const std::string& word, double max_width);
// Splits `text` at spaces into lines no wider than `max_width`; a word wider than that alone is
// split between characters.
std::vector<std::string> wrap(cairo_t* cr, const std::string& text, double max_width);

}  // namespace impulse::render
