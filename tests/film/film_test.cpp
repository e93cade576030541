// Comparisons (film.h): worlds stepped together share their moments and slow down for any pane's
// impact; eq. 8's panel is filled in with the hit's numbers.
#include "demos/film/film.h"
#include "render/camera_view.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace impulse {
namespace {

// A ball dropped from `height` m, slowed around its landing.
std::string drop(double height) {
  return R"(
[scene]
duration = 1.5
[video]
width = 320
height = 180
fps = 20
[playback]
slow_motion_impulse = 0.5
slow_motion_speed = 0.2
slow_motion_window = 0.1
[[body]]
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
radius = 0.2
mass = 1.0
restitution = 0.3
position = [0, )" + std::to_string(height) + R"(, 0]
)";
}

// Each ball lands at its own time; shown together, both panes slow down around both landings, so
// the comparison has more frames than either alone, and every pane is drawn at every frame.
TEST(Film, PanesShareTheirMomentsAndSlowDownAroundAnyPanesImpact) {
  const auto dir = testing::scratch("film_compare_test", "moments");
  const demos::Scene low = testing::scene_from(dir, drop(0.5));
  const demos::Scene high = testing::scene_from(dir, drop(1.5));
  const demos::Film low_alone({{&low, ""}}, 320, 180), high_alone({{&high, ""}}, 320, 180);
  demos::Film together({{&low, "low"}, {&high, "high"}}, 640, 360);
  // Landing at 0.28 s and 0.53 s: about 0.2 s of slow motion each, 0.8 s of video more than none.
  const int plain = 30;
  EXPECT_GT(low_alone.frame_count(), plain + 10);
  EXPECT_GT(high_alone.frame_count(), plain + 10);
  EXPECT_GT(together.frame_count(), low_alone.frame_count() + 10);
  EXPECT_GT(together.frame_count(), high_alone.frame_count() + 10);
  EXPECT_GT(together.video_time_of(1.0), high_alone.video_time_of(1.0) + 0.5);

  demos::FilmPicture picture;
  int frames = 0;
  while (together.next_frame() < together.frame_count()) {
    together.next(picture);
    ASSERT_EQ(picture.panes.size(), 2u);
    ++frames;
  }
  EXPECT_EQ(frames, together.frame_count());
  // Each pane is named, and its box is where the layout put it (the painter writes the name inside).
  ASSERT_EQ(picture.overlay.panes.size(), 2u);
  for (const auto& [name, pane] : {std::pair{"low", 0}, std::pair{"high", 1}}) {
    const render::OverlayPane& overlay_pane = picture.overlay.panes[pane];
    EXPECT_EQ(overlay_pane.label, name);
    const Eigen::Vector2i& origin = together.layout().origins[pane];
    EXPECT_EQ(overlay_pane.box.x, float(origin.x())) << name;
    EXPECT_EQ(overlay_pane.box.y, float(origin.y())) << name;
    EXPECT_EQ(overlay_pane.box.w, float(together.layout().width)) << name;
    EXPECT_EQ(overlay_pane.box.h, float(together.layout().height)) << name;
  }
}

// Each pane's own captions (CaptionCue::own, as scene_compare.h marks them) are given its index;
// the frame's are the first pane's, once.
// What a comparison's panes share (their arrows and plots drawn to one scale, one camera fitted to
// all): each largest value of any pane, every pane's moving extent, every impact in order.
TEST(Film, PanesShareTheLargestOfEachAndEveryImpact) {
  demos::TakeSummary a, b;
  a.impact_times = {0.5, 1.2};
  b.impact_times = {0.3, 0.9};
  a.largest_impulse = 2, b.largest_impulse = 5;
  a.impulse_to_fit = 1.5, b.impulse_to_fit = 0.5;
  a.largest_speed = 3, b.largest_speed = 1;
  a.plot_maxima = {4, 1}, b.plot_maxima = {2};
  b.someone_sleeps = true;
  a.moving_extent.extend(Eigen::Vector3d(0, 0, 0)).extend(Eigen::Vector3d(1, 1, 1));
  b.moving_extent.extend(Eigen::Vector3d(-2, 0.5, 0)).extend(Eigen::Vector3d(0, 3, 0.5));
  const demos::TakeSummary shared = demos::shared_summary({&a, &b});
  EXPECT_EQ(shared.impact_times, (std::vector<double>{0.3, 0.5, 0.9, 1.2}));
  EXPECT_EQ(shared.largest_impulse, 5);
  EXPECT_EQ(shared.impulse_to_fit, 1.5);
  EXPECT_EQ(shared.largest_speed, 3);
  EXPECT_EQ(shared.plot_maxima, (std::vector<double>{4, 1}));
  EXPECT_TRUE(shared.someone_sleeps);
  EXPECT_EQ(shared.moving_extent.min(), Eigen::Vector3d(-2, 0, 0));
  EXPECT_EQ(shared.moving_extent.max(), Eigen::Vector3d(1, 3, 1));
}

TEST(Film, EachPanesOwnCaptionIsNamedForItsPaneAndTheFramesComeOnce) {
  const auto dir = testing::scratch("film_compare_test", "captions");
  demos::Scene low = testing::scene_from(dir, drop(0.5));
  demos::Scene high = testing::scene_from(dir, drop(1.5));
  for (demos::Scene* scene : {&low, &high}) scene->captions = {{"for the frame", 0, 10}};
  low.captions.push_back({"low's own", 0, 10, 1, true});
  high.captions.push_back({"high's own", 0, 10, 2, true});
  demos::Film together({{&low, "low"}, {&high, "high"}}, 640, 360);
  demos::FilmPicture picture;
  together.next(picture);
  together.next(picture);
  ASSERT_EQ(picture.overlay.captions.size(), 3u);
  EXPECT_EQ(picture.overlay.captions[0].text, "for the frame");
  EXPECT_EQ(picture.overlay.captions[0].pane, -1);
  EXPECT_EQ(picture.overlay.captions[1].text, "low's own");
  EXPECT_EQ(picture.overlay.captions[1].pane, 0);
  EXPECT_EQ(picture.overlay.captions[2].text, "high's own");
  EXPECT_EQ(picture.overlay.captions[2].pane, 1);
}

// An equation that every pane shows alike is one panel for the frame; one that names each pane's
// value stays in each pane.
TEST(Film, AnEquationAllPanesShowAlikeIsOnePanelForTheFrame) {
  const auto dir = testing::scratch("film_compare_test", "shared_panel");
  const std::string same = "[[equation]]\ntex = 'J = m \\Delta v'\n";
  const demos::Scene low = testing::scene_from(dir, drop(0.5) + same + "[[equation]]\ntex = 'h = 0.5'\nposition = \"top-left\"\n");
  const demos::Scene high = testing::scene_from(dir, drop(1.5) + same + "[[equation]]\ntex = 'h = 1.5'\nposition = \"top-left\"\n");
  demos::Film together({{&low, "low"}, {&high, "high"}}, 640, 360);
  demos::FilmPicture picture;
  together.next(picture);
  together.next(picture);
  int shared = 0, own[2] = {0, 0};
  for (const render::OverlayPanel& panel : picture.overlay.panels) {
    if (panel.pane < 0) ++shared;
    else ++own[panel.pane];
  }
  EXPECT_EQ(shared, 1) << "J = m dv, once";
  EXPECT_EQ(own[0], 1) << "h = 0.5";
  EXPECT_EQ(own[1], 1) << "h = 1.5";
}

// What a pendulum hangs from is kept clear like the bodies' paths: the fixed pivot of a rod is in
// the paths that lasting elements (equation panels, plots, the legend) keep off.
TEST(Film, APivotIsKeptClearAsTheBodiesPathsAre) {
  const auto dir = testing::scratch("film_compare_test", "pivot");
  const demos::Scene scene = testing::scene_from(dir, R"(
[scene]
duration = 1.0
[video]
width = 320
height = 180
fps = 10
[camera]
position = [0, 1.5, 5]
target = [0, 1.2, 0]
[[body]]
shape = "plane"
[[body]]
name = "bob"
shape = "sphere"
radius = 0.1
position = [0.8, 1.2, 0]
[[joint]]
type = "rod"
a = "world"
b = "bob"
anchor_a = [0.0, 2.0, 0.0]
)");
  demos::Film film({{&scene, ""}}, 320, 180);
  demos::FilmPicture picture;
  film.next(picture);
  const render::CameraView view = render::make_camera_view(picture.panes[0].camera, 320, 180);
  const auto pivot = view.to_pixels(render::Vec3f(0.0f, 2.0f, 0.0f));
  ASSERT_TRUE(pivot);
  bool kept_clear = false;
  for (const render::ScreenBox& box : picture.overlay.body_paths)
    kept_clear = kept_clear || (box.x <= pivot->x() && pivot->x() <= box.right() && box.y <= pivot->y() && pivot->y() <= box.bottom());
  EXPECT_TRUE(kept_clear) << "the pivot at " << pivot->x() << ", " << pivot->y();
}

// [overlay] equation = "eq8": from the impact on, a panel fills eq. 8 in with the hit's numbers,
// the solver's impulse beside it, and the printed -(1 - e)'s, typeset (its TeX read here). 1 kg at 3 m/s onto 2 kg at rest,
// e = 0.7: J = 1.7 * 3 / 1.5 = 3.40 N s; printed 0.3 * 3 / 1.5 = 0.60 N s.
TEST(Film, EquationEightIsFilledInWithTheImpactsNumbers) {
  const auto dir = testing::scratch("film_compare_test", "equation");
  const demos::Scene scene = testing::scene_from(dir, R"(
[scene]
duration = 1.0
[world]
gravity = [0, 0, 0]
[video]
width = 320
height = 180
fps = 10
[overlay]
equation = "eq8"
[playback]
slow_motion_impulse = 1.0
[[body]]
name = "light"
shape = "sphere"
radius = 0.3
mass = 1.0
restitution = 0.7
position = [-1.5, 0, 0]
velocity = [3, 0, 0]
[[body]]
name = "heavy"
shape = "sphere"
radius = 0.3
mass = 2.0
position = [0.5, 0, 0]
)");
  demos::Film film({{&scene, ""}}, 320, 180);
  demos::FilmPicture picture;
  film.next(picture);
  EXPECT_TRUE(picture.overlay.panels.empty()) << "before the impact";
  while (film.next_frame() < film.frame_count()) film.next(picture);
  ASSERT_EQ(picture.overlay.panels.size(), 1u);
  const render::OverlayPanel& panel = picture.overlay.panels[0];
  ASSERT_EQ(panel.lines.size(), 1u);
  EXPECT_EQ(panel.lines[0].rfind("eq. 8 at t = ", 0), 0u) << panel.lines[0];
  ASSERT_TRUE(panel.math.svg);
  const std::string& tex = panel.math.tex;
  EXPECT_NE(tex.find("\\frac{-(1+0.70)\\,(-3.00)}{1/1.00 + 1/2.00} = 3.40\\ \\mathrm{N\\,s}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\text{solver: } 3.40"), std::string::npos) << tex;
  EXPECT_NE(tex.find("-(1-e)\\text{: } 0.60\\ \\mathrm{N\\,s}\\text{, too little}"), std::string::npos) << tex;
}

}  // namespace
}  // namespace impulse
