// [[check]]s from `check --simulate` and `render`: a wrong one fails with exit code 2, bad TeX is
// the scene's error with its line.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include <filesystem>
#include <regex>

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

// `check --simulate` gives its verdict after the checks: "fine" only when every one passes (never a
// "fine" above a FAIL), and each measure with its unit: the energy's rise in J and in % of its start.
TEST(Checks, CheckSimulateSaysFineOnlyWhenEveryCheckPasses) {
  const fs::path dir = work_directory();
  const std::string scene = (dir / "checked.toml").string();
  std::ofstream(scene) << std::string(kHeadOn) + R"(
[[check]]
kind = "energy"
[[check]]
kind = "at_rest"
body = "light"
from = 1.0
speed = 0.01
)";
  const testing::ProgramRun failing = run_in_process({"check", "--simulate", scene});
  EXPECT_EQ(failing.exit_code, 2) << failing.describe();
  EXPECT_EQ(failing.stdout_text, scene + ": 1 of its 2 checks FAIL (2 bodies, 2.0 s)\n") << failing.describe();
  EXPECT_TRUE(std::regex_search(failing.stderr_text,
                                std::regex(R"(pass \[\[check\]\] 1 \(energy\): rose by at most [-0-9.e+]+ J, [-0-9.e+]+ % )"
                                           R"(of its start \(allowed: 1 %\))")))
      << failing.stderr_text;
  const testing::ProgramRun passing =
      run_in_process({"check", "--simulate", scene, "--set", "check[1].body=heavy", "--set", "check[1].speed=2.5"});
  EXPECT_TRUE(passing.succeeded()) << passing.describe();
  EXPECT_EQ(passing.stdout_text, scene + ": fine, 2 bodies, 2.0 s, 2 checks pass\n") << passing.describe();
  const testing::ProgramRun read = run_in_process({"check", scene});
  EXPECT_TRUE(read.succeeded()) << read.describe();
  EXPECT_EQ(read.stdout_text, scene + ": fine, 2 bodies, 2.0 s, 2 checks (not run: --simulate runs them)\n")
      << read.describe();
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
