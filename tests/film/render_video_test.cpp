// The MP4 as a viewer gets it, decoded back through libavcodec: frame count, size and frame
// rate, the colours where a known body and the background are, and an impulse arrow where the
// contact is. Scenes are small (320x240, one second) to keep CI short.
#include "demos/film/film.h"
#include "demos/film/render_scene.h"
#include "demos/film/render_types.h"
#include "demos/scene/scene_file.h"
#include "render/camera_view.h"
#include "render/image_compare.h"
#include "render/png_io.h"
#include "tests/support/scene_scratch.h"
#include "tests/support/video_decode.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace impulse {
namespace {

namespace fs = std::filesystem;

using testing::pixel;
using testing::Rgb;

fs::path scratch(const std::string& name) { return testing::scratch("film_video_test", name); }
demos::Scene scene_from(const fs::path& dir, const std::string& text) { return testing::scene_from(dir, text); }
Rgb pixel(const render::Frame& frame, const Eigen::Vector2f& at) { return pixel(frame, int(at.x()), int(at.y())); }

// A 1 kg ball resting on the ground; its contact is at the origin. Without marks, unless the
// test adds a [draw] table.
std::string resting_ball(const std::string& draw) {
  return R"(
[scene]
duration = 1.0
[camera]
position = [0, 1.2, 5]
target = [0, 0.6, 0]
[video]
width = 320
height = 240
fps = 30
[overlay]
clock = false
legend = false
)" + draw + R"(
[[body]]
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
radius = 0.5
mass = 1.0
position = [0, 0.5, 0]
colour = "#e69f00"
)";
}

constexpr const char* kNoMarks = R"(
[draw]
contact_points = false
contact_normals = false
impulses = false
friction = false
sleeping = false
)";

TEST(RenderVideo, DecodedBackHasTheFramesSizeRateAndColours) {
  const fs::path dir = scratch("decode");
  const demos::Scene scene = scene_from(dir, resting_ball(kNoMarks));
  demos::RenderOptions options;
  options.video_path = (dir / "ball.mp4").string();
  demos::render_scene(scene, options);

  const testing::DecodedVideo video = testing::decode_video(options.video_path);
  EXPECT_EQ(video.width, 320);
  EXPECT_EQ(video.height, 240);
  EXPECT_NEAR(video.fps, 30.0, 1e-6);
  ASSERT_EQ(video.frames.size(), 30u);

  const render::CameraView view = render::make_camera_view(demos::to_render(scene.camera), 320, 240);
  const Eigen::Vector2f ball = *view.to_pixels({-0.18f, 0.72f, 0.36f});  // upper left of the ball, a light octant
  const Eigen::Vector2f sky(6, 6);
  for (const render::Frame& frame : {video.frames.front(), video.frames.back()}) {
    const Rgb on_ball = pixel(frame, ball), in_sky = pixel(frame, sky);
    EXPECT_NEAR(in_sky.r, 0.92 * 255, 12);
    EXPECT_NEAR(in_sky.g, 0.94 * 255, 12);
    EXPECT_NEAR(in_sky.b, 0.97 * 255, 12);
    EXPECT_GT(on_ball.r, on_ball.b + 100) << "orange: " << on_ball.r << "," << on_ball.g << "," << on_ball.b;
    EXPECT_GT(on_ball.r, 150);
  }
}

// Two panes side by side (`impulse compare`'s film), each its own scene drawn into its half of
// every frame, through the same threads as one pane (picturing, drawing, encoding).
TEST(RenderVideo, TwoPanesShowEachItsOwnScene) {
  const fs::path dir = scratch("panes");
  const demos::Scene orange = scene_from(scratch("pane_orange"), resting_ball(kNoMarks));
  std::string blue_text = resting_ball(kNoMarks);
  blue_text.replace(blue_text.find("#e69f00"), 7, "#0072b2");
  const demos::Scene blue = scene_from(scratch("pane_blue"), blue_text);
  demos::RenderOptions options;
  options.video_path = (dir / "panes.mp4").string();
  demos::render_panes({{&orange, "orange"}, {&blue, "blue"}}, options);

  const testing::DecodedVideo video = testing::decode_video(options.video_path);
  ASSERT_EQ(video.frames.size(), 30u);
  const demos::PaneLayout layout = demos::pane_layout(2, 320, 240, false, false);
  ASSERT_EQ(layout.origins.size(), 2u);
  const render::CameraView view = render::make_camera_view(demos::to_render(orange.camera), layout.width, layout.height);
  const Eigen::Vector2f ball = *view.to_pixels({-0.18f, 0.72f, 0.36f});
  for (const render::Frame& frame : {video.frames.front(), video.frames.back()}) {
    const Rgb left = pixel(frame, layout.origins[0].cast<float>() + ball);
    const Rgb right = pixel(frame, layout.origins[1].cast<float>() + ball);
    EXPECT_GT(left.r, left.b + 100) << "orange: " << left.r << "," << left.g << "," << left.b;
    EXPECT_GT(right.b, right.r + 100) << "blue: " << right.r << "," << right.g << "," << right.b;
  }
}

// The normal impulse on the ball, drawn from the contact up: at 10 m per N s a resting step's
// impulse (m g dt = 0.16 N s) is about 1.6 m long, so the arrow leaves the ball's top (1 m).
TEST(RenderVideo, AnImpulseArrowStandsOnTheContact) {
  const fs::path dir = scratch("arrow");
  const demos::Scene scene = scene_from(dir, resting_ball(R"(
[draw]
contact_points = false
contact_normals = false
impulses = true
impulse_scale = 10.0
friction = false
sleeping = false
)"));
  demos::RenderOptions options;
  options.video_path = (dir / "arrow.mp4").string();
  demos::render_scene(scene, options);
  const testing::DecodedVideo video = testing::decode_video(options.video_path);
  ASSERT_EQ(video.frames.size(), 30u);

  const render::CameraView view = render::make_camera_view(demos::to_render(scene.camera), 320, 240);
  const Eigen::Vector2f above_ball = *view.to_pixels({0.0f, 1.25f, 0.0f});   // on the arrow, above the ball
  const Eigen::Vector2f beside = *view.to_pixels({0.6f, 1.25f, 0.0f});       // same height, off the arrow
  for (size_t index : {size_t(6), size_t(20)}) {
    const Rgb on_arrow = pixel(video.frames[index], above_ball);
    const Rgb off_arrow = pixel(video.frames[index], beside);
    EXPECT_GT(on_arrow.b, on_arrow.r + 90) << "frame " << index << ": blue (#0072b2) above the contact, got "
                                           << on_arrow.r << "," << on_arrow.g << "," << on_arrow.b;
    EXPECT_LT(off_arrow.b, off_arrow.r + 40) << "frame " << index << ": no arrow beside it";
  }
}

TEST(RenderVideo, ChosenFramesAsPng) {
  const fs::path dir = scratch("png");
  const demos::Scene scene = scene_from(dir, resting_ball(kNoMarks));
  demos::RenderOptions options;
  options.png_directory = (dir / "frames").string();
  options.png_frames = {0, 29};
  demos::render_scene(scene, options);
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_00000.png"));
  EXPECT_TRUE(fs::exists(dir / "frames" / "frame_00029.png"));
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame_00001.png"));
  EXPECT_EQ(render::read_png((dir / "frames" / "frame_00029.png").string()).width, 320);
}

// Slow motion stretches the video around an impact: more frames than duration x fps.
TEST(RenderVideo, SlowMotionAroundAnImpactAddsFrames) {
  const fs::path dir = scratch("slow");
  std::string text = resting_ball(kNoMarks);
  text.replace(text.find("position = [0, 0.5, 0]"), 22, "position = [0, 1.5, 0]");  // dropped 1 m
  text += "\n[playback]\nslow_motion_impulse = 1.0\nslow_motion_speed = 0.25\n";
  const demos::Scene scene = scene_from(dir, text);
  demos::RenderOptions options;
  options.video_path = (dir / "slow.mp4").string();
  demos::render_scene(scene, options);
  const testing::DecodedVideo video = testing::decode_video(options.video_path);
  EXPECT_GT(video.frames.size(), 40u) << "the impact (J = 1 kg x 1.7 x 4.4 m/s) should slow playback";
}

// A ball falling 2 m onto the ground (the landing at 0.64 s), 30 frames of 320x240, no marks
// drawn; `overlay` and `extra` are added to its [overlay] table and its end. Renders it with a
// poster and returns the video's frames and the poster.
struct PosterRun {
  testing::DecodedVideo video;
  render::Frame poster;
};
PosterRun render_fall_with_poster(const std::string& name, const std::string& overlay, const std::string& extra) {
  const fs::path dir = scratch(name);
  std::string text = resting_ball(kNoMarks) + extra;
  const std::string rest = "position = [0, 0.5, 0]";
  text.replace(text.find(rest), rest.size(), "position = [0, 2.5, 0]");  // falling: every frame differs
  const std::string clock = "clock = false\n";
  text.replace(text.find(clock), clock.size(), clock + overlay);
  const demos::Scene scene = scene_from(dir, text);
  demos::RenderOptions options;
  options.video_path = (dir / (name + ".mp4")).string();
  options.poster_path = demos::poster_path(options.video_path);
  demos::render_scene(scene, options);
  PosterRun run{testing::decode_video(options.video_path), render::read_png(options.poster_path)};
  EXPECT_EQ(run.video.frames.size(), 30u);
  return run;
}

// Which frame of the video the poster is. The decoded frames went through H.264 (yuv420p halves
// the colour planes): the poster is the frame that differs from it least, by far (-1 if none is).
int poster_frame_of(const PosterRun& run) {
  std::vector<int> differing;
  for (const render::Frame& frame : run.video.frames) differing.push_back(render::compare_images(frame, run.poster).differing_pixels);
  const int closest = int(std::min_element(differing.begin(), differing.end()) - differing.begin());
  for (size_t i = 0; i < differing.size(); ++i)
    if (int(i) != closest && !(differing[i] > 4 * differing[closest] + 50)) {
      ADD_FAILURE() << "frames " << i << " and " << closest << " are both close: " << ::testing::PrintToString(differing);
      return -1;
    }
  return closest;
}

// The poster beside a video is one of its frames: with no impulse labelled or drawn and no impact
// to slow the video, the middle one.
TEST(RenderVideo, ThePosterIsTheMiddleFrameWithNothingToShow) {
  const PosterRun run = render_fall_with_poster("poster_middle", "label = \"none\"\n", "");
  ASSERT_EQ(run.video.frames.size(), 30u);
  EXPECT_EQ(poster_frame_of(run), 15);
}

// By default the poster shows the largest labelled impulse: a frame of those that hold the
// landing's marks on screen (0.4 s of video from the first frame after it), not the middle one.
TEST(RenderVideo, ThePosterShowsTheLargestLabelledImpulse) {
  const PosterRun run = render_fall_with_poster("poster_impulse", "", "");
  ASSERT_EQ(run.video.frames.size(), 30u);
  const int landing = int(std::ceil(std::sqrt(2 * 2.0 / 9.81) * 30));  // 0.639 s: frame 20
  const int poster = poster_frame_of(run);
  EXPECT_GE(poster, landing);
  EXPECT_LT(poster, landing + 12);
}

// [playback] poster chooses the moment, and a caption fading there moves the poster to the nearest
// frame where it is whole: the caption fades in from 0.5 to 0.59 s, so 0.55 s (frame 17) gives way
// to frame 18 (0.6 s), not 16 (0.53 s, still fading).
TEST(RenderVideo, AChosenPosterMomentAvoidsAFadingCaption) {
  const PosterRun run = render_fall_with_poster(
      "poster_chosen", "label = \"none\"\n",
      "[playback]\nposter = 0.55\n[[caption]]\ntext = \"Falling\"\nstart = 0.5\nend = 1.0\n");
  ASSERT_EQ(run.video.frames.size(), 30u);
  EXPECT_EQ(poster_frame_of(run), 18);
}

}  // namespace
}  // namespace impulse
