// The overlay's layout (render/overlay_layout.h): elements in free space, one after another; never
// over each other nor outside the frame, over bodies only when nothing else is free; and, over
// seeded random frames, never an overlap whatever the requests.
#include "render/overlay_layout.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace impulse {
namespace {

using render::LayoutGround;
using render::LayoutRequest;
using render::Placement;
using render::ScreenBox;
using render::Spot;
using render::Vec2f;

constexpr int kWidth = 640, kHeight = 360;

LayoutGround ground() {
  LayoutGround ground;
  ground.width = kWidth;
  ground.height = kHeight;
  ground.gap = 4;
  return ground;
}

// A w x h element that would like its `align` point at (x, y).
LayoutRequest element(float w, float h, float x, float y, Vec2f align = Vec2f(0, 0)) {
  LayoutRequest request;
  request.sizes = {Vec2f(w, h)};
  request.spots = {Spot{Vec2f(x, y), align}};
  return request;
}

bool inside_frame(const ScreenBox& box) { return render::contains({0, 0, float(kWidth), float(kHeight)}, box); }

TEST(OverlayLayout, AFreeSpotIsTakenAsAskedAndTheNextElementGoesUnderIt) {
  LayoutRequest legend = element(200, 80, 10, 10);
  legend.slide = {3, 1};  // a column: down rather than across
  const std::vector<Placement> placed = render::lay_out(ground(), {element(300, 40, 10, 10), legend});
  ASSERT_EQ(placed[0].size, 0);
  EXPECT_EQ(placed[0].box.x, 10);
  EXPECT_EQ(placed[0].box.y, 10);
  ASSERT_EQ(placed[1].size, 0);
  EXPECT_FALSE(render::overlaps(placed[0].box, placed[1].box));
  EXPECT_EQ(placed[1].box.x, 10) << "under the first, not beside it";
  EXPECT_NEAR(placed[1].box.y, 10 + 40 + 4, 1e-3) << "just under, the gap apart";
}

TEST(OverlayLayout, AnElementAskedOutsideTheFrameComesInside) {
  const std::vector<Placement> placed = render::lay_out(ground(), {element(100, 30, kWidth - 20, kHeight + 50)});
  ASSERT_EQ(placed[0].size, 0);
  EXPECT_TRUE(inside_frame(placed[0].box));
}

TEST(OverlayLayout, AnElementMovesOffAMovingBodyToFreeSpace) {
  LayoutGround over_ball = ground();
  over_ball.moving = {{30, 20, 60, 60}};  // a ball under the top-left corner
  const std::vector<Placement> placed = render::lay_out(over_ball, {element(200, 80, 10, 10)});
  ASSERT_EQ(placed[0].size, 0);
  EXPECT_EQ(placed[0].covered, 0);
  EXPECT_FALSE(render::overlaps(placed[0].box, over_ball.moving[0]));
}

TEST(OverlayLayout, BodiesAreCoveredOnlyWhenNoFreePlaceIsLeft) {
  LayoutGround crowded = ground();
  crowded.moving = {{0, 0, float(kWidth), float(kHeight)}};  // bodies everywhere
  const std::vector<Placement> placed = render::lay_out(crowded, {element(200, 80, 10, 10)});
  ASSERT_EQ(placed[0].size, 0);
  EXPECT_GT(placed[0].covered, 0);
  EXPECT_EQ(placed[0].box.x, 10) << "it stays where asked, covering no more there than anywhere";
  EXPECT_EQ(placed[0].box.y, 10);
}

TEST(OverlayLayout, AnElementShrinksWhenOnlyItsSmallerFormFitsFree) {
  LayoutGround ground_left = ground();
  ground_left.moving = {{0, 100, float(kWidth), float(kHeight - 100)}};  // free only above y = 100
  LayoutRequest caption = element(500, 150, 10, 10);
  caption.sizes.push_back(Vec2f(500, 80));  // wrapped wider, or set smaller
  const std::vector<Placement> placed = render::lay_out(ground_left, {caption});
  EXPECT_EQ(placed[0].size, 1);
  EXPECT_EQ(placed[0].covered, 0);
}

TEST(OverlayLayout, AnElementWithNoRoomAtAllIsLeftOut) {
  const std::vector<Placement> placed =
      render::lay_out(ground(), {element(kWidth, kHeight, 0, 0), element(50, 20, 10, 10)});
  EXPECT_EQ(placed[0].size, 0);
  EXPECT_EQ(placed[1].size, -1) << "drawn nowhere rather than over the first";
}

TEST(OverlayLayout, ElementsPreferTheSpaceBetweenPanesAndStayInsideTheirBounds) {
  LayoutGround panes = ground();
  panes.panes = {{0, 60, 310, 180}, {330, 60, 310, 180}};
  LayoutRequest legend = element(150, 50, 10, 70);  // asked over the first pane's corner
  LayoutRequest name = element(80, 16, 10, 230, Vec2f(0, 1));
  name.bounds = panes.panes[1];  // the second pane's name stays inside it
  const std::vector<Placement> placed = render::lay_out(panes, {legend, name});
  ASSERT_EQ(placed[0].size, 0);
  for (const ScreenBox& pane : panes.panes) EXPECT_FALSE(render::overlaps(placed[0].box, pane));
  ASSERT_EQ(placed[1].size, 0);
  EXPECT_TRUE(render::contains(panes.panes[1], placed[1].box));
}

TEST(OverlayLayout, ALabelKeepsOffTheArrowsItAvoids) {
  LayoutRequest label = element(70, 14, 200, 100);
  label.spots.push_back(Spot{Vec2f(200, 130), Vec2f(0, 0)});
  label.avoid = {{Vec2f(190, 105), Vec2f(400, 105)}};  // an arrow through the first spot
  label.lasting = false;
  const std::vector<Placement> placed = render::lay_out(ground(), {label});
  ASSERT_EQ(placed[0].size, 0);
  EXPECT_EQ(placed[0].box.y, 130) << "its second spot, clear of the arrow";
}

// A lasting element whose first spot is taken stays where it went while that stays free, and an
// element asked under another goes under it wherever that went.
TEST(OverlayLayout, LastingElementsStayPutAndFollowWhatTheyGoUnder) {
  render::OverlayLayout layout;
  LayoutGround frame = ground();
  LayoutRequest plot = element(120, 50, kWidth - 10, 10, Vec2f(1, 0));
  plot.key = 1;
  LayoutRequest second = plot;
  second.key = 2;
  second.under = 0;
  frame.moving = {{kWidth - 150.0f, 0, 150, 80}};  // a ball where the column starts
  const ScreenBox first = layout.place(frame, {plot, second})[0].box;
  const ScreenBox below = layout.place(frame, {plot, second})[1].box;
  EXPECT_NEAR(below.x + below.w, first.x + first.w, 1e-3) << "the second plot right under the first";
  EXPECT_NEAR(below.y, first.bottom() + frame.gap, 1e-3);
  frame.moving = {{300, 300, 20, 20}};  // the ball has gone: the corner is free, but the plot stays
  EXPECT_EQ(layout.place(frame, {plot, second})[0].box.y, first.y);
  frame.moving = {{first.x + 10, first.y + 10, 20, 20}};  // a ball comes under it: now it moves
  const Placement moved = layout.place(frame, {plot, second})[0];
  EXPECT_EQ(moved.covered, 0);
  EXPECT_FALSE(render::overlaps(moved.box, frame.moving[0]));
}

// Seeded random frames: up to 14 elements of random sizes and spots over random bodies and
// panes. Every element placed is inside the frame and its bounds, and no two overlap.
TEST(OverlayLayout, NoTwoElementsEverOverlapOrLeaveTheFrame) {
  std::mt19937 random(29);
  std::uniform_real_distribution<float> unit(0, 1);
  int placed_count = 0, left_out = 0;
  for (int round = 0; round < 300; ++round) {
    LayoutGround frame = ground();
    for (int i = int(unit(random) * 12); i > 0; --i)
      frame.moving.push_back({unit(random) * kWidth, unit(random) * kHeight, 5 + unit(random) * 120, 5 + unit(random) * 120});
    if (unit(random) < 0.3f) frame.panes = {{5, 50, 300, 170}, {335, 50, 300, 170}};
    std::vector<LayoutRequest> requests;
    for (int i = 2 + int(unit(random) * 12); i > 0; --i) {
      LayoutRequest request = element(10 + unit(random) * 300, 10 + unit(random) * 120, unit(random) * 1.2f * kWidth - 50,
                                      unit(random) * 1.2f * kHeight - 30, Vec2f(unit(random), unit(random)));
      request.sizes.push_back(request.sizes.front() * 0.7f);
      if (unit(random) < 0.3f) request.bounds = {unit(random) * 300, unit(random) * 150, 200 + unit(random) * 300, 100 + unit(random) * 200};
      if (unit(random) < 0.3f) request.avoid = {{Vec2f(unit(random) * kWidth, unit(random) * kHeight), Vec2f(unit(random) * kWidth, unit(random) * kHeight)}};
      requests.push_back(request);
    }
    const std::vector<Placement> placed = render::lay_out(frame, requests);
    ASSERT_EQ(placed.size(), requests.size());
    for (size_t i = 0; i < placed.size(); ++i) {
      if (placed[i].size < 0) {
        ++left_out;
        continue;
      }
      ++placed_count;
      SCOPED_TRACE("round " + std::to_string(round) + ", element " + std::to_string(i));
      EXPECT_TRUE(inside_frame(placed[i].box));
      if (requests[i].bounds.w > 0) {
        EXPECT_TRUE(render::contains(requests[i].bounds, placed[i].box));
      }
      EXPECT_NEAR(placed[i].box.w, requests[i].sizes[placed[i].size].x(), 1e-3);
      for (size_t j = 0; j < i; ++j) {
        if (placed[j].size >= 0) {
          EXPECT_FALSE(render::overlaps(placed[i].box, placed[j].box)) << "with element " << j;
        }
      }
    }
  }
  EXPECT_GT(placed_count, 5 * left_out) << "most elements find a place";
}

}  // namespace
}  // namespace impulse
