// The 2D overlay: the frame is untouched where the layer paints nothing; the label sits beside its
// arrow's tip (captions in whole scenes: film_caption_test.cpp).
#include "render/overlay_painter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace impulse {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

TEST(Overlay, CompositesOnlyWhereItPaintsInTheRightColour) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 0)};
  for (size_t i = 0; i < frame.rgba.size(); i += 4) {
    frame.rgba[i] = 40;
    frame.rgba[i + 1] = 200;
    frame.rgba[i + 2] = 90;
    frame.rgba[i + 3] = 255;
  }
  const render::Frame before = frame;
  render::Overlay overlay;
  overlay.captions = {{"Caption", 1.0f}};
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(overlay, frame);
  // The top half has nothing painted.
  for (int y = 0; y < kHeight / 2; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(frame.rgba[(size_t(y) * kWidth + x) * 4 + c], before.rgba[(size_t(y) * kWidth + x) * 4 + c]);
  // The caption box is dark grey over green: dark, still a little green, never red or blue.
  bool found_box = false;
  for (int y = kHeight * 3 / 4; y < kHeight && !found_box; ++y) {
    const uint8_t* p = &frame.rgba[(size_t(y) * kWidth + kWidth / 2) * 4];
    if (p[1] < 80) {
      found_box = true;
      EXPECT_GT(p[1], p[0]) << "green shows through the box";
      EXPECT_GT(p[1], p[2]);
      EXPECT_EQ(p[3], 255);
    }
  }
  EXPECT_TRUE(found_box);
  // A second paint with nothing clears what the first painted.
  render::Frame again = before;
  painter.paint(render::Overlay{}, again);
  EXPECT_TRUE(again.rgba == before.rgba);
}

TEST(Overlay, LabelSitsBesideItsAnchor) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 255)};
  render::Overlay overlay;
  overlay.labels = {{render::Vec2f(100, 120), "J = 2.41 N\u00b7s", {0.0f, 0.45f, 0.7f}, {}}};
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(overlay, frame);
  int inked_right = 0, inked_left = 0;
  for (int y = 100; y < 125; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const uint8_t* p = &frame.rgba[(size_t(y) * kWidth + x) * 4];
      if (p[2] > p[0] + 60) (x > 100 ? inked_right : inked_left)++;
    }
  }
  EXPECT_GT(inked_right, 30) << "blue letters to the right of the anchor";
  EXPECT_EQ(inked_left, 0);
}

// A label whose first place, to the right of and above its anchor, would cover an arrow goes to a
// place that covers none.
TEST(Overlay, LabelMovesOffTheArrowItWouldCover) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 255)};
  render::Overlay overlay;
  // An arrow running right from the anchor, through where the label would go.
  const render::ScreenSegment arrow{render::Vec2f(100, 113), render::Vec2f(300, 113)};
  overlay.labels = {{render::Vec2f(100, 120), "J = 2.41 N\u00b7s", {0.0f, 0.45f, 0.7f}, {arrow}}};
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(overlay, frame);
  int inked = 0, inked_on_arrow = 0;
  for (int y = 90; y < 150; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const uint8_t* p = &frame.rgba[(size_t(y) * kWidth + x) * 4];
      if (p[2] <= p[0] + 60) continue;
      ++inked;
      if (x >= 100 && std::abs(y - 113) <= 2) ++inked_on_arrow;
    }
  }
  EXPECT_GT(inked, 30) << "the label is written";
  EXPECT_EQ(inked_on_arrow, 0) << "and covers no part of the arrow";
}

// A word longer than the frame is wide, in a title or a caption, is split between characters: the
// title's panel keeps to its column (clear of the clock's), the caption's box to the frame.
TEST(Overlay, AWordWiderThanItsBoxIsSplitBetweenCharacters) {
  const std::string word(300, 'W');
  render::OverlayPainter painter(kWidth, kHeight);
  render::Frame dark{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 0)};
  render::Overlay title;
  title.title = word;
  painter.paint(title, dark);
  const double scale = kHeight / 720.0;
  const int column_end = int(kWidth - 20 * scale - 330 * scale + 12 * scale * 2);  // the title's column and padding
  int rightmost = -1, inked = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (dark.rgba[(size_t(y) * kWidth + x) * 4] > 100) {
        rightmost = std::max(rightmost, x);
        ++inked;
      }
  EXPECT_GT(inked, 1000) << "the title's panel, over several lines";
  EXPECT_LE(rightmost, column_end);

  render::Frame light{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 255)};
  render::Overlay caption;
  caption.captions = {{word, 1.0f}};
  painter.paint(caption, light);
  int dark_rows = 0;
  for (int y = 0; y < kHeight; ++y) {
    bool row_dark = false;
    for (int x = 0; x < kWidth; ++x) {
      const bool is_dark = light.rgba[(size_t(y) * kWidth + x) * 4] < 128;
      row_dark |= is_dark;
      if (x < 2 || x >= kWidth - 2) {
        EXPECT_FALSE(is_dark) << "the caption's box reaches the frame's edge at y = " << y;
      }
    }
    dark_rows += row_dark;
  }
  EXPECT_GT(dark_rows, 20) << "a box of several lines";
}

}  // namespace
}  // namespace impulse
