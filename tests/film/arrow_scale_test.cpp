// The automatic impulse scale (marks.h): fitted to the hits, not to the loads of resting contacts
// (a load fitted before a hit drew the waiting bodies' arrows long and the hit's cut and far too
// long); one hard hit must not shrink every other hit's arrow to nothing, its own arrow cut and its
// value written beside it.
#include "demos/film/film.h"
#include "demos/film/marks.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace impulse {
namespace {

using demos::ImpulsePeak;

TEST(ImpulseScale, FitsTheLargestHitUnlessOneMomentOutweighsAllOtherHitsFourTimes) {
  // A landing of 12 N s (two steps), then 0.33 N s a step at rest, a load: the landing is fitted.
  std::vector<ImpulsePeak> landing{{1.00, 12.0, true}, {1.02, 3.0, true}};
  for (int k = 0; k < 60; ++k) landing.push_back({1.5 + k / 60.0, 0.33, false});
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit(landing), 12.0);
  // A load first, then a small hit and a hard one: the hard one outweighs the small one four times.
  std::vector<ImpulsePeak> hits{{0.1, 0.2, false}, {0.2, 0.2, false}, {1.0, 1.5, true}, {2.0, 12.0, true}};
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit(hits), 1.5);
  // Bounces that shrink by e = 0.7 each: no moment outweighs the next one four times.
  const std::vector<ImpulsePeak> bounces{{0.5, 10.0}, {1.5, 7.0}, {2.3, 4.9}, {3.0, 3.4}};
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit(bounces), 10.0);
  // One moment alone: nothing else to fit.
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit({{1.0, 12.0}, {1.1, 0.5}}), 12.0);
  // Nothing hits (a stack at rest): the loads are fitted.
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit({{0.1, 0.5, false}, {0.2, 0.7, false}}), 0.7);
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit({}), 0.0);
}

bool same(const render::Colour& a, const render::Colour& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

double longest_impulse_arrow(const render::DrawList& list) {
  double longest = 0;
  for (const render::ArrowItem& arrow : list.arrows)
    if (same(arrow.colour, demos::mark_colour::normal_impulse)) longest = std::max(longest, double(arrow.direction.norm()));
  return longest;
}

// A 2 kg ball dropped 2 m lands with about 12.5 N s, then rests at m g dt = 0.33 N s a step, a
// load. The landing sets the scale: its arrow is drawn whole, about the fitted 1.5 m (a round
// scale), and the resting arrow to the same scale, 0.33 / 12.5 of it.
TEST(ImpulseScale, ALandingSetsTheScaleAndTheRestingArrowIsDrawnToIt) {
  const auto dir = testing::scratch("film_arrow_scale_test", "landing");
  const demos::Scene scene = testing::scene_from(dir, R"(
[scene]
duration = 1.5
[video]
width = 320
height = 180
fps = 30
[overlay]
label = "none"
[[body]]
shape = "plane"
restitution = 0.0
[[body]]
name = "ball"
shape = "sphere"
radius = 0.3
mass = 2.0
restitution = 0.0
position = [0, 2.3, 0]
)");
  demos::Film film({{&scene, ""}}, 320, 180);
  demos::FilmPicture picture;
  double longest = 0, resting = 0;
  while (film.next_frame() < film.frame_count()) {
    film.next(picture);
    ASSERT_EQ(picture.panes.size(), 1u);
    const double arrow = longest_impulse_arrow(picture.panes[0]);
    longest = std::max(longest, arrow);
    resting = arrow;  // the last frame's: at rest since about 0.7 s
  }
  EXPECT_GT(longest, 0.75) << "the landing's arrow, fitted: a round scale draws it 0.75-1.5 m long";
  EXPECT_LE(longest, 1.5 + 1e-6) << "and not cut";
  EXPECT_GT(resting, 0.0) << "the resting ball's arrow is drawn";
  EXPECT_LT(resting, 0.05 * longest) << "to the landing's scale: 0.33 N s against about 12.5";
}

// A block rests on the ground; at 0.6 s a ball rolled at it hits it. Before the hit the block's
// load is drawn to the hit's scale (short), and the hit's arrow is not cut: the scale is the hit's.
TEST(ImpulseScale, ALoadBeforeAHitIsDrawnToTheHitsScale) {
  const auto dir = testing::scratch("film_arrow_scale_test", "load_then_hit");
  const demos::Scene scene = testing::scene_from(dir, R"(
[scene]
duration = 1.0
[video]
width = 320
height = 180
fps = 30
[overlay]
label = "none"
[[body]]
shape = "plane"
friction = 0.0
[[body]]
name = "block"
shape = "box"
size = [0.3, 0.3, 0.3]
mass = 0.5
position = [0, 0.15, 0]
friction = 0.0
[[body]]
name = "ball"
shape = "sphere"
radius = 0.15
mass = 2.0
friction = 0.0
position = [-2.0, 0.15, 0]
velocity = [3.0, 0, 0]
)");
  demos::Film film({{&scene, ""}}, 320, 180);
  demos::FilmPicture picture;
  double before_hit = 0, longest = 0;
  while (film.next_frame() < film.frame_count()) {
    film.next(picture);
    const double arrow = longest_impulse_arrow(picture.panes[0]);
    if (picture.time < 0.4) before_hit = std::max(before_hit, arrow);
    longest = std::max(longest, arrow);
  }
  EXPECT_LE(longest, 1.5 + 1e-6) << "the hit's arrow, fitted, not cut";
  EXPECT_GT(longest, 0.75);
  EXPECT_GT(before_hit, 0.0) << "the block's load is drawn";
  EXPECT_LT(before_hit, 0.25 * longest) << "to the hit's scale";
}

}  // namespace
}  // namespace impulse
