// The automatic impulse scale (marks.h): one hard landing must not shrink every other arrow of the
// run to nothing; its own arrow is cut and its value written beside it.
#include "demos/film/film.h"
#include "demos/film/marks.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace impulse {
namespace {

using demos::ImpulsePeak;

TEST(ImpulseScale, FitsTheLargestUnlessOneMomentOutweighsAllOthersFourTimes) {
  // A landing of 12 N s (two steps), then 0.33 N s a step at rest: the rest is what is fitted.
  std::vector<ImpulsePeak> landing{{1.00, 12.0}, {1.02, 3.0}};
  for (int k = 0; k < 60; ++k) landing.push_back({1.5 + k / 60.0, 0.33});
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit(landing), 0.33);
  // Bounces that shrink by e = 0.7 each: no moment outweighs the next one four times.
  const std::vector<ImpulsePeak> bounces{{0.5, 10.0}, {1.5, 7.0}, {2.3, 4.9}, {3.0, 3.4}};
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit(bounces), 10.0);
  // One moment alone: nothing else to fit.
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit({{1.0, 12.0}, {1.1, 0.5}}), 12.0);
  EXPECT_DOUBLE_EQ(demos::impulse_to_fit({}), 0.0);
}

bool same(const render::Colour& a, const render::Colour& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

double longest_impulse_arrow(const render::DrawList& list) {
  double longest = 0;
  for (const render::ArrowItem& arrow : list.arrows)
    if (same(arrow.colour, demos::mark_colour::normal_impulse)) longest = std::max(longest, double(arrow.direction.norm()));
  return longest;
}

// A 2 kg ball dropped 2 m lands with about 12.5 N s, then rests at m g dt = 0.33 N s a step. The
// resting arrow is drawn long enough to see; the landing's is cut to 1.5 times the fitted length,
// with its value written at its tip.
TEST(ImpulseScale, ALandingsArrowIsCutAndWrittenAndTheRestingArrowStaysVisible) {
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
  bool written = false;
  while (film.next_frame() < film.frame_count()) {
    film.next(picture);
    ASSERT_EQ(picture.panes.size(), 1u);
    const double arrow = longest_impulse_arrow(picture.panes[0]);
    longest = std::max(longest, arrow);
    resting = arrow;  // the last frame's: at rest since about 0.7 s
    for (const render::OverlayLabel& label : picture.overlay.labels)
      written = written || (label.text.rfind("J = 1", 0) == 0 && label.text.find("N\u00b7s") != std::string::npos);
  }
  EXPECT_LE(longest, 2.25 + 1e-6) << "the landing's arrow is cut to 1.5 x the fitted 1.5 m";
  EXPECT_GT(longest, 2.0) << "and it is the longest arrow of the run";
  EXPECT_GT(resting, 0.5) << "the resting ball's arrow, fitted (0.33 N s), not shrunk by the landing's 12 N s";
  EXPECT_TRUE(written) << "the cut arrow's value is written beside it";
}

}  // namespace
}  // namespace impulse
