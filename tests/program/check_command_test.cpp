// [[check]]s from `check --simulate` and `render`: a wrong one fails with exit code 2, bad TeX is
// the scene's error with its line.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include <filesystem>

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

// A head-on hit's momentum holds; a deliberately wrong check (the light sphere at rest) fails with
// exit code 2, from `check --simulate` and from `render`, which still writes its video.
TEST(Checks, AWrongCheckFailsWithItsExitCodeAndARightOnePasses) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "checked.toml") << std::string(kHeadOn) + R"(
[video]
width = 160
height = 120
fps = 10
[[check]]
kind = "momentum"
tolerance = 1e-9
[[check]]
kind = "at_rest"
body = "light"
from = 1.0
speed = 0.01
)";
  const testing::ProgramRun checked = run_in_process({"check", "--simulate", (dir / "checked.toml").string()});
  EXPECT_EQ(checked.exit_code, 2) << checked.describe();
  EXPECT_NE(checked.stderr_text.find("pass [[check]] 1 (momentum): changed by"), std::string::npos) << checked.stderr_text;
  EXPECT_NE(checked.stderr_text.find("FAIL [[check]] 2 (at_rest of 'light'): fastest 1 m/s (below 0.01)"),
            std::string::npos)
      << checked.stderr_text;
  const testing::ProgramRun rendered =
      run_in_process({"-q", "render", (dir / "checked.toml").string(), "-o", (dir / "checked.mp4").string()});
  EXPECT_EQ(rendered.exit_code, 2) << rendered.describe();
  EXPECT_TRUE(fs::exists(dir / "checked.mp4"));
  const testing::ProgramRun fixed = run_in_process(
      {"check", "--simulate", (dir / "checked.toml").string(), "--set", "check[1].body=heavy", "--set", "check[1].speed=2.5"});
  EXPECT_TRUE(fixed.succeeded()) << fixed.describe();
}

// TeX that latex refuses is the scene's error, with its file and line, from `check` and before a
// render writes anything.
TEST(Checks, BadTexInAnEquationIsASceneErrorWithItsLine) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "bad_tex.toml") << std::string(kHeadOn) + R"(
[[equation]]
tex = 'J = \fracc{1}{2}'
)";
  int line = 0;
  {
    std::ifstream file(dir / "bad_tex.toml");
    std::string text;
    for (int n = 1; std::getline(file, text); ++n)
      if (text.rfind("tex = ", 0) == 0) line = n;
  }
  const std::string expected = (dir / "bad_tex.toml").string() + ":" + std::to_string(line) +
                               ": [[equation]] 1 field 'tex': LaTeX: Undefined control sequence \\fracc";
  const testing::ProgramRun checked = run_in_process({"check", (dir / "bad_tex.toml").string()});
  EXPECT_EQ(checked.exit_code, 1) << checked.describe();
  EXPECT_NE(checked.stderr_text.find(expected), std::string::npos) << checked.stderr_text;
  const testing::ProgramRun rendered =
      run_in_process({"-q", "render", (dir / "bad_tex.toml").string(), "-o", (dir / "bad_tex.mp4").string()});
  EXPECT_EQ(rendered.exit_code, 1) << rendered.describe();
  EXPECT_NE(rendered.stderr_text.find(expected), std::string::npos) << rendered.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "bad_tex.mp4"));
}

}  // namespace
}  // namespace impulse
