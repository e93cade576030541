// The 2D overlay: the frame is untouched where the layer paints nothing; the label sits beside its
// arrow's tip; every element inside the box it reports (captions in whole scenes: caption_test.cpp).
#include "render/overlay_layout.h"
#include "render/overlay_painter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
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

// Every kind of element at once, in a comparison of two panes over a small frame: each is painted
// inside the box the painter reports (what --layout-report writes), the boxes are inside the
// frame and apart, each pane's name inside its pane, and nothing is painted outside the boxes.
// The legend's sleeping swatch is drawn as a sleeping body is: its colour paled towards grey, with
// darker diagonal stripes (shaders.cpp's hatch), so both shades fill the swatch.
TEST(Overlay, TheLegendsSleepingSwatchIsPaleAndHatched) {
  constexpr int kW = 1280, kH = 720;
  render::Overlay overlay;
  const render::Colour blue{0.0f, 0.45f, 0.70f};
  overlay.legend = {{blue, "asleep (pale, hatched)", 0.0f, false, true}};
  render::Frame frame{kW, kH, std::vector<uint8_t>(size_t(kW) * kH * 4, 255)};
  render::OverlayPainter painter(kW, kH);
  painter.paint(overlay, frame);
  const render::PaintedLayout& layout = painter.layout();
  ASSERT_EQ(layout.elements.size(), 1u);
  const render::ScreenBox& box = layout.elements[0].box;
  // pale = (c + 0.45 (grey - c)) 0.7 + 0.25 = (0.367, 0.540, 0.636); a stripe 0.8 of it.
  const int pale[3] = {94, 138, 162}, stripe[3] = {75, 110, 130};
  auto near = [](const uint8_t* p, const int* c) { return std::abs(p[0] - c[0]) <= 10 && std::abs(p[1] - c[1]) <= 10 && std::abs(p[2] - c[2]) <= 10; };
  int pale_pixels = 0, stripe_pixels = 0, plain_pixels = 0;
  for (int y = int(box.y) + 15; y < int(box.y) + 26; ++y)
    for (int x = int(box.x) + 14; x < int(box.x) + 34; ++x) {
      const uint8_t* p = &frame.rgba[(size_t(y) * kW + x) * 4];
      pale_pixels += near(p, pale);
      stripe_pixels += near(p, stripe);
      plain_pixels += std::abs(p[0] - 0) <= 10 && std::abs(p[1] - 115) <= 10 && std::abs(p[2] - 179) <= 10;
    }
  EXPECT_GT(pale_pixels, 40);
  EXPECT_GT(stripe_pixels, 20);
  EXPECT_EQ(plain_pixels, 0) << "the colour itself, not paled";
}

TEST(Overlay, EveryElementIsPaintedInsideItsReportedBoxAndNoTwoOverlap) {
  constexpr int kW = 640, kH = 360;
  render::Overlay overlay;
  overlay.title = "Two panes, every element";
  overlay.clock = "t = 1.25 s";
  overlay.playback = "slow motion \u00d70.20";
  overlay.captions = {{"The first caption, long enough to wrap over two lines of the frame's width.", 1.0f},
                      {"The second caption.", 0.6f}};
  overlay.legend = {{{0.0f, 0.0f, 0.0f}, "contact point", 0.0f, true}, {{0.0f, 0.45f, 0.7f}, "normal impulse: 1 N\u00b7s", 40.0f}};
  render::Plot energy{"kinetic energy", "J", 2.0f, 0.0f, 0.0f, 5.0f, {{{0.9f, 0.6f, 0.0f}, {{0.0f, 4.0f}, {1.0f, 2.0f}}}}};
  overlay.plots = {energy, energy};
  overlay.plots_row_top = 250;
  overlay.panes = {{{8, 60, 300, 170}, "e = 0.2", {0.0f, 0.45f, 0.7f}}, {{332, 60, 300, 170}, "e = 0.8", {0.8f, 0.4f, 0.0f}}};
  overlay.labels = {{render::Vec2f(150, 150), "J = 2.41 N\u00b7s", {0.0f, 0.45f, 0.7f}, {}, 0}};
  render::OverlayPanel panel;
  panel.place = render::PanelPlace::top_right;
  panel.lines = {"eq. 8", "J = 3.40 N\u00b7s"};
  panel.pane = 1;
  overlay.panels = {panel};
  overlay.bodies = {{0, "ball", {140, 160, 30, 30}, true}};

  const uint8_t background = 90;
  render::Frame frame{kW, kH, std::vector<uint8_t>(size_t(kW) * kH * 4, background)};
  render::OverlayPainter painter(kW, kH);
  painter.paint(overlay, frame);
  const render::PaintedLayout& layout = painter.layout();
  EXPECT_TRUE(layout.dropped.empty());
  std::set<std::string> names;
  for (const render::PaintedElement& element : layout.elements) names.insert(element.name);
  EXPECT_EQ(names, (std::set<std::string>{"title", "clock", "caption 1", "caption 2", "legend", "plot 1", "plot 2",
                                          "pane label 1", "pane label 2", "panel 1", "label 1"}));
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const render::ScreenBox& box = layout.elements[i].box;
    EXPECT_TRUE(render::contains({0, 0, float(kW), float(kH)}, box)) << layout.elements[i].name;
    for (size_t j = 0; j < i; ++j)
      EXPECT_FALSE(render::overlaps(box, layout.elements[j].box)) << layout.elements[i].name << " and " << layout.elements[j].name;
    if (layout.elements[i].name.rfind("pane label ", 0) == 0) {
      const int pane = layout.elements[i].name.back() - '1';
      EXPECT_TRUE(render::contains(overlay.panes[pane].box, box)) << layout.elements[i].name;
    }
    if (layout.elements[i].name == "panel 1") {
      EXPECT_TRUE(render::contains(overlay.panes[1].box, box));
    }
    if (layout.elements[i].name == "label 1") {
      EXPECT_FALSE(render::overlaps(box, overlay.bodies[0].box));
    }
  }
  // A text's halo and anti-aliased edges reach a few pixels past its box; nothing further.
  const float reach = 2 + 4 * kH / 720.0f;
  int painted = 0, outside = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const uint8_t* p = &frame.rgba[(size_t(y) * kW + x) * 4];
      if (p[0] == background && p[1] == background && p[2] == background) continue;
      ++painted;
      bool inside = false;
      for (const render::PaintedElement& element : layout.elements) {
        const render::ScreenBox& b = element.box;
        inside |= x + 1 > b.x - reach && x < b.right() + reach && y + 1 > b.y - reach && y < b.bottom() + reach;
      }
      outside += !inside;
    }
  }
  EXPECT_GT(painted, 10000);
  EXPECT_EQ(outside, 0) << "pixels painted outside every reported box";
}

// A label that cannot sit at its arrow's tip (a body all round it) is joined to it by a leader
// line, from beside the anchor to the label's box, painted in the label's colour; one beside its
// tip has none.
TEST(Overlay, ALabelAwayFromItsAnchorIsJoinedToItByALeaderLine) {
  constexpr int kW = 640, kH = 360;
  const uint8_t background = 255;
  render::Frame frame{kW, kH, std::vector<uint8_t>(size_t(kW) * kH * 4, background)};
  render::Overlay overlay;
  overlay.labels = {{render::Vec2f(320, 180), "J = 2.41 N\u00b7s", {0.0f, 0.45f, 0.7f}, {}},
                    {render::Vec2f(80, 300), "J = 0.50 N\u00b7s", {0.0f, 0.45f, 0.7f}, {}}};
  overlay.bodies = {{0, "block", {220, 90, 200, 180}, true}};  // the first label's anchor in its middle
  render::OverlayPainter painter(kW, kH);
  painter.paint(overlay, frame);
  const render::PaintedLayout& layout = painter.layout();
  ASSERT_EQ(layout.leaders.size(), 1u);
  const render::PaintedLeader& leader = layout.leaders[0];
  EXPECT_EQ(leader.label, 0);
  EXPECT_LT((leader.from - overlay.labels[0].anchor).norm(), 6.0f) << "it starts beside the anchor";
  const render::ScreenBox* box = nullptr;
  for (const render::PaintedElement& element : layout.elements)
    if (element.name == "label 1") box = &element.box;
  ASSERT_NE(box, nullptr);
  // Off the body, but for the layout's coarse grid (it sums bodies into cells: a pixel or two).
  const render::ScreenBox& body = overlay.bodies[0].box;
  const float across = std::min(box->right(), body.right()) - std::max(box->x, body.x);
  const float down = std::min(box->bottom(), body.bottom()) - std::max(box->y, body.y);
  EXPECT_TRUE(across <= 2 || down <= 2) << "the label left the body: " << box->x << " " << box->y << " " << box->w << " " << box->h;
  EXPECT_LT(std::abs(leader.to.x() - std::clamp(leader.to.x(), box->x, box->right())) +
                std::abs(leader.to.y() - std::clamp(leader.to.y(), box->y, box->bottom())), 0.5f) << "it ends at the box";
  // Painted along its length in the label's colour: bluish pixels within a pixel of each point.
  for (const float share : {0.25f, 0.5f, 0.75f}) {
    const render::Vec2f at = leader.from + (leader.to - leader.from) * share;
    bool bluish = false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const uint8_t* p = &frame.rgba[(size_t(std::lround(at.y()) + dy) * kW + size_t(std::lround(at.x()) + dx)) * 4];
        bluish = bluish || (p[0] < 160 && p[2] > p[0] + 40);
      }
    EXPECT_TRUE(bluish) << "at " << share << " of the leader";
  }
}

// A pane's own caption goes inside its pane, at its top; the frame's caption under the panes.
TEST(Overlay, APanesOwnCaptionIsInsideItsPaneAndTheFramesUnderThePanes) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 255)};
  render::Overlay overlay;
  const float pane_w = kWidth / 2.0f - 12, pane_h = kHeight * 0.6f;
  overlay.panes = {{{4, 40, pane_w, pane_h}, "one", {0.0f, 0.45f, 0.7f}}, {{kWidth / 2.0f + 8, 40, pane_w, pane_h}, "two", {0.8f, 0.4f, 0.0f}}};
  overlay.captions = {{"under both", 1.0f, -1}, {"e = 0.9", 1.0f, 1}};
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(overlay, frame);
  std::map<std::string, render::ScreenBox> placed;
  for (const render::PaintedElement& element : painter.layout().elements) placed[element.name] = element.box;
  ASSERT_TRUE(placed.count("caption 1") && placed.count("caption 2")) << painter.layout().elements.size();
  const render::ScreenBox own = placed["caption 2"], pane = overlay.panes[1].box;
  EXPECT_TRUE(render::contains(pane, own)) << own.x << " " << own.y << " " << own.w << " " << own.h;
  EXPECT_LT(own.y, pane.y + pane.h / 3) << "at the pane's top";
  EXPECT_GE(placed["caption 1"].y, pane.y + pane.h) << "the frame's caption is under the panes";
}

// A pane's equation panel stays in its pane while a place there keeps off where the bodies go;
// where every place in it would cover their paths, it goes under its pane, in its pane's column.
TEST(Overlay, APanesPanelGoesUnderItsPaneRatherThanOverTheBodiesPaths) {
  constexpr int kW = 640, kH = 360;
  render::Frame frame{kW, kH, std::vector<uint8_t>(size_t(kW) * kH * 4, 255)};
  render::Overlay overlay;
  overlay.panes = {{{8, 40, 300, 200}, "one", {0.0f, 0.45f, 0.7f}}, {{332, 40, 300, 200}, "two", {0.8f, 0.4f, 0.0f}}};
  const render::ScreenBox path{20, 50, 276, 180};  // pane one's bodies sweep it nearly whole
  overlay.body_paths = {path};
  render::OverlayPanel panel;
  panel.place = render::PanelPlace::top_left;
  panel.lines = {"eq. 8", "J = 3.40 N\u00b7s"};
  panel.pane = 0;
  overlay.panels = {panel, panel};
  overlay.panels[1].pane = 1;
  render::OverlayPainter painter(kW, kH);
  painter.paint(overlay, frame);
  std::map<std::string, render::ScreenBox> placed;
  for (const render::PaintedElement& element : painter.layout().elements) placed[element.name] = element.box;
  ASSERT_TRUE(placed.count("panel 1") && placed.count("panel 2"));
  const render::ScreenBox one = placed["panel 1"], two = placed["panel 2"];
  const render::ScreenBox& pane = overlay.panes[0].box;
  EXPECT_FALSE(render::overlaps(one, path)) << one.x << " " << one.y << " " << one.w << " " << one.h;
  EXPECT_TRUE(render::contains({pane.x, pane.y, pane.w, float(kH) - pane.y}, one)) << "in its pane's column";
  EXPECT_GT(one.bottom(), pane.bottom()) << "under its pane";
  EXPECT_TRUE(render::contains(overlay.panes[1].box, two)) << "a pane with room keeps its panel";
  EXPECT_LT(two.y, overlay.panes[1].box.y + 40) << "at its top left";
}

}  // namespace
}  // namespace impulse
