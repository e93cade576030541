// --set as a student uses it: it changes what the trace shows, is refused naming itself, and is
// recorded in the video.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include "tests/support/video_decode.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

TEST(Set, FrictionOffChangesWhatTheTraceShows) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  const std::string scene = (dir / "slide.toml").string();
  ASSERT_TRUE(run_in_process({"simulate", scene, "--trace", (dir / "with.csv").string()}).succeeded());
  const testing::ProgramRun without =
      run_in_process({"simulate", scene, "--set", "world.friction=false", "--trace", (dir / "without.csv").string()});
  ASSERT_TRUE(without.succeeded()) << without.describe();
  EXPECT_NEAR(number(last_of(read_csv(dir / "with.csv"), "box"), "vx_m_per_s"), 0.0, 1e-3);  // stopped by mu g
  EXPECT_NEAR(number(last_of(read_csv(dir / "without.csv"), "box"), "vx_m_per_s"), 3.0, 1e-6);
}

TEST(Set, ABadValueOrPathIsRefusedNamingTheArgument) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  const std::string scene = (dir / "slide.toml").string();
  struct Case {
    std::string setting, says;
  };
  for (const Case& each : std::vector<Case>{
           {"body[box].restitution=2", "--set body[box].restitution=2: [[body]] 'box' field 'restitution': must be >= 0 and <= 1, got 2"},
           {"world.frictoin=false", "--set world.frictoin=false: [world] field 'frictoin': unknown field; did you mean 'friction'?"},
           {"body[bx].mass=2", "--set body[bx].mass=2: no [[body]] is named 'bx'; did you mean 'box'?"},
           {"world.method=projektion", "unknown value 'projektion'; did you mean 'projection'?"},
           {"wrld.friction=false", "--set wrld.friction=false: a scene has no table 'wrld'; did you mean 'world'?"},
           {"body[5].mass=2", "--set body[5].mass=2: there are 2 [[body]] tables, numbered from 0"},
           // One value, nothing after it: a second line or trailing words are refused, never dropped.
           {"body[box].mass=1\nrestitution=5",
            "--set body[box].mass=1\\nrestitution=5: a value is one line, and a line break follows '1'; give each field "
            "its own --set"},
           {"body[box].mass=1 restitution=5", "--set body[box].mass=1 restitution=5: cannot read the value '1 restitution=5': "},
           {"body[box].colour=\"#ff0000\" x", "cannot read the value '\"#ff0000\" x': "}}) {
    const testing::ProgramRun result = run_in_process({"check", scene, "--set", each.setting});
    EXPECT_EQ(result.exit_code, 1) << each.setting;
    EXPECT_NE(result.stderr_text.find(each.says), std::string::npos) << result.stderr_text;
  }
}

// The video records the settings that changed it, in its comment tag.
TEST(Set, TheVideoRecordsTheSettings) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  const fs::path video = dir / "slide.mp4";
  const testing::ProgramRun result = run_in_process(
      {"-q", "render", (dir / "slide.toml").string(), "--set", "world.friction=false", "-o", video.string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();
  EXPECT_EQ(testing::decode_video(video.string()).comment, "--set world.friction=false");
}

}  // namespace
}  // namespace impulse
