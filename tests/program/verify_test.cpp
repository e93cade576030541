// `impulse verify` run as a course's CI runs it: goldens recorded at --quality low pass the next
// run, also at other llvmpipe vector widths and frame rates, and without --quality (the manifest's
// size); a recoloured ball, a recoloured sleeping (pale) block and a ball moved by a quarter of its
// radius fail, the moved body named; another size is refused with what to re-run; the report, the
// actual image, the diff and the strip exist whenever named.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "demos/film/moments.h"
#include "render/png_io.h"
#include "tests/support/child_process.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

fs::path work_directory() {
  const fs::path dir = fs::temp_directory_path() / ("impulse_verify_" + std::to_string(getpid()) + "_" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

testing::ChildResult impulse(const std::vector<std::string>& arguments, const testing::ChildSettings& settings = {}) {
  std::vector<std::string> argv = {IMPULSE_PROGRAM, "-q"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return testing::run_child(argv, settings);
}

bool has(const testing::ChildResult& result, const std::string& text) {
  return result.stderr_text.find(text) != std::string::npos;
}

// A ball of radius 0.2 m dropped on a plane; the impact slows the video.
constexpr const char* kDrop = R"(
[scene]
title = "Drop"
duration = 1.2
[camera]
position = [0, 1.2, 5]
target = [0, 0.6, 0]
[playback]
slow_motion_impulse = 1.0
[[body]]
name = "ground"
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
radius = 0.2
position = [0, 1.0, 0]
restitution = 0.6
)";

// The goldens of kDrop at --quality low, recorded afresh for each test.
struct Goldens {
  fs::path dir = work_directory();
  std::string scene = (dir / "drop.toml").string();
  std::string golden = (dir / "golden").string();
  testing::ChildResult update;
  Goldens() {
    std::ofstream(scene) << kDrop;
    update = impulse({"verify", scene, "--golden", golden, "--quality", "low", "--update"});
  }
  testing::ChildResult verify(std::vector<std::string> more, const testing::ChildSettings& settings = {}) const {
    std::vector<std::string> arguments = {"verify", scene, "--golden", golden};
    arguments.insert(arguments.end(), more.begin(), more.end());
    return impulse(arguments, settings);
  }
};

TEST(Verify, RecordsTheStartMiddleEndAndImpactsWithAManifestAndPoses) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  for (const char* name : {"t_0.000.png", "t_0.600.png", "t_1.200.png", "manifest.toml", "poses.csv"})
    EXPECT_TRUE(fs::exists(fs::path(goldens.golden) / name)) << name;
  int impacts = 0;  // the ball first lands after sqrt(2 * 0.8 / 9.81) = 0.40 s
  for (const auto& entry : fs::directory_iterator(goldens.golden)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("t_0.4", 0) == 0) ++impacts;
  }
  EXPECT_GE(impacts, 1) << "no still at the first impact";
  const render::Frame still = render::read_png((fs::path(goldens.golden) / "t_0.600.png").string());
  EXPECT_EQ(still.width, 854);
  EXPECT_EQ(still.height, 480);
}

TEST(Verify, PassesItsGoldensAtEveryVectorWidthAndAnotherFrameRate) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  const testing::ChildResult same = goldens.verify({"--quality", "low"});
  EXPECT_TRUE(same.succeeded()) << same.describe();
  EXPECT_TRUE(fs::exists(fs::path(goldens.golden) / "report.html"));
  for (const char* width : {"128", "256"}) {
    testing::ChildSettings settings;
    settings.set = {std::string("LP_NATIVE_VECTOR_WIDTH=") + width};
    const testing::ChildResult pinned = goldens.verify({"--quality", "low"}, settings);
    EXPECT_TRUE(pinned.succeeded()) << "LP_NATIVE_VECTOR_WIDTH=" << width << ": " << pinned.describe();
  }
  // The moments, not frame numbers: at 30 frames/s the same moments are shown.
  const testing::ChildResult faster = goldens.verify({"--quality", "low", "--fps", "30"});
  EXPECT_TRUE(faster.succeeded()) << faster.describe();
}

TEST(Verify, FailsARecolouredBallWithTheReportAndStrip) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  const testing::ChildResult black = goldens.verify({"--quality", "low", "--set", "body[ball].colour=\"#000000\""});
  EXPECT_EQ(black.exit_code, 2) << black.describe();
  EXPECT_TRUE(has(black, "t = 0.600 s DIFFERS from " + goldens.golden + "/t_0.600.png: largest region")) << black.stderr_text;
  for (const char* name : {"t_0.600.actual.png", "t_0.600.diff.png", "t_0.600.strip.png", "report.html"})
    EXPECT_TRUE(fs::exists(fs::path(goldens.golden) / name)) << name;
  std::ifstream report(fs::path(goldens.golden) / "report.html");
  const std::string html((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("t_0.600.strip.png"), std::string::npos);
  EXPECT_NE(html.find("FAILED"), std::string::npos);
  // Passing again removes what the failure left.
  EXPECT_TRUE(goldens.verify({"--quality", "low"}).succeeded());
  EXPECT_FALSE(fs::exists(fs::path(goldens.golden) / "t_0.600.strip.png"));
}

// A quarter of the radius, 5 cm, sideways: the picture and the pose both differ, the body named.
TEST(Verify, FailsABallMovedByAQuarterOfItsRadiusNamingIt) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  const testing::ChildResult moved = goldens.verify({"--quality", "low", "--set", "body[ball].position=[0.05, 1.0, 0]"});
  EXPECT_EQ(moved.exit_code, 2) << moved.describe();
  EXPECT_TRUE(has(moved, "t = 0.000 s DIFFERS")) << moved.stderr_text;
  EXPECT_TRUE(has(moved, "t = 0.000 s: body 'ball' moved 0.0500 m (by [0.0500, 0.0000, 0.0000])")) << moved.stderr_text;
  EXPECT_FALSE(has(moved, "body 'ground' moved")) << moved.stderr_text;
}

// Without --quality, --width, --height or --fps the goldens' size and frame rate (their manifest's)
// are rendered, not the scene's own 1280x720 at 30 fps: goldens recorded at --quality low pass.
TEST(Verify, ComparesAtTheGoldensSizeUnlessTold) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  const testing::ChildResult plain = goldens.verify({});
  EXPECT_TRUE(plain.succeeded()) << plain.describe();
  const testing::ChildResult faster = goldens.verify({"--fps", "30"});  // the goldens' 854x480, at 30 fps
  EXPECT_TRUE(faster.succeeded()) << faster.describe();
}

// A block at rest, seen from its side: asleep from about 1 s, drawn pale and hatched.
constexpr const char* kBlock = R"(
[scene]
title = "A block at rest"
duration = 2.0
[camera]
position = [0.8, 0.25, 3.5]
target = [0, 0.2, 0]
[[body]]
name = "ground"
shape = "plane"
[[body]]
name = "block"
shape = "box"
size = [0.8, 0.4, 0.4]
position = [0, 0.2, 0]
colour = "#009e73"
)";

// Recoloured green -> vermillion, the block differs awake and asleep: pale, its front face is 0.09
// apart in YIQ, under the 0.1 a few pixels must differ by, but over the whole face.
TEST(Verify, FailsARecolouredSleepingBody) {
  const fs::path dir = work_directory();
  const std::string scene = (dir / "block.toml").string(), golden = (dir / "golden").string();
  std::ofstream(scene) << kBlock;
  const testing::ChildResult update = impulse({"verify", scene, "--golden", golden, "--quality", "low", "--at", "0,2", "--update"});
  ASSERT_TRUE(update.succeeded()) << update.describe();
  const testing::ChildResult same = impulse({"verify", scene, "--golden", golden, "--quality", "low"});
  EXPECT_TRUE(same.succeeded()) << same.describe();
  const testing::ChildResult recoloured =
      impulse({"verify", scene, "--golden", golden, "--quality", "low", "--set", "body[block].colour=\"#d55e00\""});
  EXPECT_EQ(recoloured.exit_code, 2) << recoloured.describe();
  EXPECT_TRUE(has(recoloured, "t = 0.000 s DIFFERS")) << recoloured.stderr_text;
  EXPECT_TRUE(has(recoloured, "t = 2.000 s DIFFERS from " + golden + "/t_2.000.png: a faint difference over an area"))
      << recoloured.stderr_text;
}

TEST(Verify, RefusesAnotherSizeSayingWhatToRerun) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  const testing::ChildResult medium = goldens.verify({"--quality", "medium", "--at", "0.6"});
  EXPECT_EQ(medium.exit_code, 2) << medium.describe();
  EXPECT_TRUE(has(medium, "the goldens are 854x480 at 15 fps (--quality low), this run 1280x720 at 30 fps (--quality medium): "
                          "re-run with --quality low, or with --update to record new goldens"))
      << medium.stderr_text;
  for (const char* name : {"t_0.600.actual.png", "t_0.600.diff.png", "t_0.600.strip.png", "report.html"})
    EXPECT_TRUE(fs::exists(fs::path(goldens.golden) / name)) << name;
}

TEST(Verify, RefusesNothingToCompareWith) {
  const Goldens goldens;
  ASSERT_TRUE(goldens.update.succeeded()) << goldens.update.describe();
  const testing::ChildResult missing = goldens.verify({"--quality", "low", "--at", "0.7"});
  EXPECT_EQ(missing.exit_code, 1) << missing.describe();
  EXPECT_TRUE(has(missing, "no golden at t = 0.700 s in " + goldens.golden)) << missing.stderr_text;
  const testing::ChildResult none = impulse({"verify", goldens.scene, "--golden", (goldens.dir / "none").string()});
  EXPECT_EQ(none.exit_code, 1) << none.describe();
  EXPECT_TRUE(has(none, "no " + (goldens.dir / "none").string() + "/manifest.toml: record the goldens first")) << none.stderr_text;
  const testing::ChildResult bad = goldens.verify({"--at", "0.5,x"});
  EXPECT_EQ(bad.exit_code, 1) << bad.describe();
  EXPECT_TRUE(has(bad, "--at wants moments in seconds")) << bad.stderr_text;
}

// Moments to the millisecond, sorted, once each; anything else refused naming the option.
TEST(Verify, MomentsAreParsedToTheMillisecond) {
  EXPECT_EQ(demos::parse_moments("2,0.5,0.5004,1"), (std::vector<double>{0.5, 1, 2}));
  EXPECT_EQ(demos::moment_name(0.4166), "t_0.417");
  EXPECT_EQ(demos::moment_name(12), "t_12.000");
  for (const char* bad : {"", "0.5,", "-1", "x", "1e300", "nan", "0.5 "}) {
    EXPECT_THROW(demos::parse_moments(bad, "--at"), std::invalid_argument) << "'" << bad << "'";
  }
}

// render --png takes moments too, parsed as verify parses them, beside frame numbers.
TEST(Verify, RenderTakesMomentsAndFrames) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "drop.toml") << kDrop;
  const testing::ChildResult rendered =
      impulse({"render", (dir / "drop.toml").string(), "-o", (dir / "drop.mp4").string(), "--quality", "low", "--png",
               (dir / "png").string(), "--at", "0.5,1", "--frames", "3"});
  ASSERT_TRUE(rendered.succeeded()) << rendered.describe();
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir / "png")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_00003.png", "t_0.500.png", "t_1.000.png"}));
  EXPECT_TRUE(fs::exists(dir / "drop.mp4"));
}

}  // namespace
}  // namespace impulse
