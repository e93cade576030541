// Text in the overlay (render/overlay_text.h): Greek, mathematical signs and emoji in a title or
// caption are drawn as their glyphs, not as the empty box a font draws for a character it lacks.
// Each glyph's ink, in a caption, is compared with that box, drawn for a character no font has.
#include "render/overlay_painter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace impulse {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
const std::string kMissing = "\U0010FFFD";  // a noncharacter: no font has a glyph for it

// The ink of a caption holding `text`: its light pixels (white letters, a coloured ball) on the
// caption's dark box, as a mask from the ink's top-left corner.
struct Ink {
  int width = 0, height = 0, count = 0;
  std::vector<bool> lit;  // width x height
  bool at(int x, int y) const { return x < width && y < height && lit[size_t(y) * width + x]; }
};

Ink caption_ink(const std::string& text) {
  render::OverlayPainter painter(kWidth, kHeight);
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 0)};
  render::Overlay overlay;
  overlay.captions = {{text, 1.0f}};
  painter.paint(overlay, frame);
  const render::ScreenBox box = painter.layout().elements.at(0).box;
  auto lit = [&](int x, int y) {
    const uint8_t* p = &frame.rgba[(size_t(y) * kWidth + x) * 4];
    return std::max({p[0], p[1], p[2]}) > 120;
  };
  int left = kWidth, right = -1, top = kHeight, bottom = -1;
  for (int y = int(box.y) + 1; y < int(box.bottom()) - 1; ++y) {
    for (int x = int(box.x) + 1; x < int(box.right()) - 1; ++x) {
      if (!lit(x, y)) continue;
      left = std::min(left, x);
      right = std::max(right, x);
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  }
  Ink ink;
  if (right < 0) return ink;
  ink.width = right - left + 1;
  ink.height = bottom - top + 1;
  ink.lit.assign(size_t(ink.width) * ink.height, false);
  for (int y = 0; y < ink.height; ++y)
    for (int x = 0; x < ink.width; ++x)
      if (lit(left + x, top + y)) {
        ink.lit[size_t(y) * ink.width + x] = true;
        ++ink.count;
      }
  return ink;
}

// Of the pixels either inks (each from its ink's corner), the share both do.
double overlap(const Ink& a, const Ink& b) {
  int both = 0, either = 0;
  for (int y = 0; y < std::max(a.height, b.height); ++y) {
    for (int x = 0; x < std::max(a.width, b.width); ++x) {
      both += a.at(x, y) && b.at(x, y);
      either += a.at(x, y) || b.at(x, y);
    }
  }
  return either > 0 ? double(both) / either : 1.0;
}

// The share of the ink's bounding box that is inked: a box drawn round nothing is mostly empty.
double fill(const Ink& ink) { return ink.count > 0 ? double(ink.count) / (ink.width * ink.height) : 0.0; }

TEST(OverlayText, GreekMathematicsAndEmojiAreDrawnAsGlyphsNotAsTheMissingBox) {
  const Ink missing = caption_ink(kMissing);
  ASSERT_GT(missing.count, 20) << "the missing character's box has some ink";
  for (const std::string glyph : {"\u03b1", "\u03b2", "\u03b3", "\u2211", "\u221a", "\U0001F3B1"}) {
    SCOPED_TRACE(glyph);
    const Ink ink = caption_ink(glyph);
    EXPECT_GT(ink.count, 15) << "inked";
    EXPECT_LT(overlap(ink, missing), 0.35) << "not the box drawn for a missing character";
  }
  // The billiard ball's white disc fills most of its ink's box; a box drawn round nothing (a
  // font's .notdef, Pango's box of hex digits) is an outline with at most a few digits in it.
  EXPECT_GT(fill(caption_ink("\U0001F3B1")), 0.5);
}

// The whole caption of the issue: each part of the line inked (Pango sets it as one line, the
// emoji from Noto Color Emoji, the rest from DejaVu Sans).
TEST(OverlayText, ACaptionOfGreekMathematicsAndAnEmojiIsWrittenWhole) {
  const Ink ink = caption_ink("\u03b1\u03b2\u03b3 \u2211 \u221a \U0001F3B1");
  ASSERT_GT(ink.width, 60);
  int lit[4] = {0, 0, 0, 0};
  for (int y = 0; y < ink.height; ++y)
    for (int x = 0; x < ink.width; ++x) lit[std::min(3, 4 * x / ink.width)] += ink.at(x, y);
  for (int quarter = 0; quarter < 4; ++quarter) EXPECT_GT(lit[quarter], 20) << "quarter " << quarter;
  EXPECT_LT(overlap(ink, caption_ink("\u03b1\u03b2\u03b3 \u2211 \u221a " + kMissing)), 0.8)
      << "the ball is not drawn as the missing character's box";
}

}  // namespace
}  // namespace impulse
