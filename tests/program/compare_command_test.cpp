// `impulse compare`: one video, a pane per value, decoded back; a bad --vary refused saying why.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include "demos/film/film.h"
#include "tests/support/scene_scratch.h"
#include "tests/support/video_decode.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

// Two balls dropped side by side; `compare` varies the right one's restitution.
constexpr const char* kTwoBalls = R"(
[scene]
title = "Restitution"
duration = 1.5
[camera]
position = [0, 1.0, 4.5]
target = [0, 0.8, 0]
[video]
width = 960
height = 540
fps = 20
crf = 10
[overlay]
label = "none"
[[body]]
name = "ground"
shape = "plane"
[[body]]
name = "steady"
shape = "sphere"
radius = 0.3
mass = 1.0
restitution = 0.0
position = [-1.2, 1.5, 0]
[[body]]
name = "varied"
shape = "sphere"
radius = 0.3
mass = 1.0
restitution = 0.5
position = [1.2, 1.5, 0]
)";

// Pixels of one half of two panes (above the label) more than 40 levels apart in a channel.
int differing_pixels(const render::Frame& frame, const demos::PaneLayout& layout, bool right_half) {
  int count = 0;
  const int x0 = right_half ? layout.width / 2 : 0;
  for (int y = 0; y < layout.height * 4 / 5; ++y) {
    for (int x = x0; x < x0 + layout.width / 2; ++x) {
      const testing::Rgb a = testing::pixel(frame, layout.origins[0].x() + x, layout.origins[0].y() + y);
      const testing::Rgb b = testing::pixel(frame, layout.origins[1].x() + x, layout.origins[1].y() + y);
      count += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 40;
    }
  }
  return count;
}

// compare: one video, a pane per value, decoded back. The panes differ where the setting acts (the
// right ball: near rest at e = 0.1, high at e = 0.9) and agree where it does not (the left ball,
// the ground), at the same simulated moments. The left ball's impulse arrow has one length in
// both panes: the arrows share a scale (with a scale per pane it would be 1.7 times longer at
// e = 0.1, where the right ball's landing is the smaller impulse).
TEST(Compare, PanesDifferWhereTheSettingDiffersAndAgreeWhereItDoesNot) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "balls.toml") << kTwoBalls;
  const fs::path video = dir / "balls.mp4";
  const testing::ProgramRun result = run_in_process({"-q", "compare", (dir / "balls.toml").string(), "--vary",
                                               "body[varied].restitution=0.1, 0.9", "-o", video.string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();
  const testing::DecodedVideo decoded = testing::decode_video(video.string());
  ASSERT_EQ(decoded.width, 960);
  ASSERT_EQ(decoded.height, 540);
  ASSERT_EQ(decoded.frames.size(), 30u);
  EXPECT_EQ(decoded.comment, "pane 1: --set body[varied].restitution=0.1; pane 2: --set body[varied].restitution=0.9");
  const demos::PaneLayout layout = demos::pane_layout(2, 960, 540, false, false);
  // 0.55 s: both balls just bounced, their arrows drawn; 0.95 s: the bouncy one near its top.
  for (const int frame : {11, 19}) {
    EXPECT_LT(differing_pixels(decoded.frames[frame], layout, false), 20) << "frame " << frame;
    EXPECT_GT(differing_pixels(decoded.frames[frame], layout, true), 150) << "frame " << frame;
  }
  // Before the first bounce the worlds are the same.
  EXPECT_LT(differing_pixels(decoded.frames[5], layout, true), 20);
  EXPECT_EQ(result.stderr_text.find("moved alike"), std::string::npos) << result.stderr_text;
}

// Friction varied where nothing slides (two balls dropped straight down): the panes move alike,
// step for step, and the lecturer is told so, with the panes' labels, as the video is written.
TEST(Compare, PanesThatMoveAlikeAreNamedInAWarning) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "balls.toml") << kTwoBalls;
  const fs::path video = dir / "balls.mp4";
  const testing::ProgramRun result =
      run_in_process({"-q", "compare", (dir / "balls.toml").string(), "--vary", "world.friction=true,false", "-o", video.string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();
  EXPECT_TRUE(fs::exists(video));
  EXPECT_NE(result.stderr_text.find("warning: panes 1 (world.friction = true) and 2 (world.friction = false) moved alike, step for step"),
            std::string::npos)
      << result.stderr_text;
}

TEST(Compare, ABadVaryIsRefusedSayingWhy) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "balls.toml") << kTwoBalls;
  const std::string scene = (dir / "balls.toml").string(), video = (dir / "x.mp4").string();
  const testing::ProgramRun shared = run_in_process({"-q", "compare", scene, "--vary", "video.fps=10,20", "-o", video});
  EXPECT_EQ(shared.exit_code, 1) << shared.describe();
  EXPECT_NE(shared.stderr_text.find("every pane of a comparison has the same video"), std::string::npos)
      << shared.stderr_text;
  const testing::ProgramRun one = run_in_process({"-q", "compare", scene, "--vary", "world.friction=false", "-o", video});
  EXPECT_EQ(one.exit_code, 1) << one.describe();
  EXPECT_NE(one.stderr_text.find("give two to four values"), std::string::npos) << one.stderr_text;
  const testing::ProgramRun typo = run_in_process({"-q", "compare", scene, "--vary", "body[varied].restitutoin=0.1,0.9", "-o", video});
  EXPECT_EQ(typo.exit_code, 1) << typo.describe();
  EXPECT_NE(typo.stderr_text.find("did you mean 'restitution'"), std::string::npos) << typo.stderr_text;
  EXPECT_FALSE(fs::exists(video));
}

}  // namespace
}  // namespace impulse
