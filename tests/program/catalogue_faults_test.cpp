// A catalogue that fails on one scene: the scenes it finished keep their videos and posters, the
// failed one leaves neither a poster nor a temporary file (a poster only ever sits beside its
// complete video), and the gallery shows what was finished and marks what failed. The failure
// is a file-size limit (`ulimit -f`) that the second scene's video passes near its end, after its
// poster frame; sequentially and with --jobs 2.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/child_process.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

constexpr int kExitOutput = 3;

// A ball on the ground for half a second: a small video and poster.
constexpr const char* kSmall = R"(# A ball at rest.
[scene]
title = "Small"
duration = 0.5
[[body]]
shape = "plane"
[[body]]
shape = "sphere"
radius = 0.5
position = [0, 0.5, 0]
)";

std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

class CatalogueFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = fs::temp_directory_path() / ("impulse_catalogue_faults_" + std::to_string(getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(work_);
    fs::create_directories(work_ / "scenes");
    std::ofstream(work_ / "scenes/a_small.toml") << kSmall;
    fs::copy_file(fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/bounce.toml", work_ / "scenes/b_bounce.toml");
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(work_);
  }

  testing::ChildResult catalogue(const fs::path& out, const std::vector<std::string>& more,
                                 testing::ChildSettings settings = {}) const {
    std::vector<std::string> argv = {IMPULSE_PROGRAM, "-q", "catalogue", "--scenes", (work_ / "scenes").string(),
                                     "-o", out.string(), "--quality", "low"};
    argv.insert(argv.end(), more.begin(), more.end());
    settings.working_directory = IMPULSE_SOURCE_DIR;
    return testing::run_child(argv, settings);
  }

  fs::path work_;
};

TEST_F(CatalogueFaults, AFailedSceneLeavesNoPosterAndTheGalleryMarksIt) {
  // Without a limit, to learn how large the second video grows; then a limit it passes near its end.
  const fs::path whole = work_ / "whole";
  const testing::ChildResult unlimited = catalogue(whole, {});
  ASSERT_TRUE(unlimited.succeeded()) << unlimited.describe();
  const long limit = long(fs::file_size(whole / "b_bounce.mp4")) * 9 / 10;
  for (const char* small_file : {"a_small.mp4", "a_small.png", "b_bounce.png", "index.html"})
    ASSERT_LT(long(fs::file_size(whole / small_file)), limit) << small_file << " would pass the limit too";

  for (const std::vector<std::string>& jobs : {std::vector<std::string>{}, std::vector<std::string>{"--jobs", "2"}}) {
    const fs::path out = work_ / (jobs.empty() ? "one_at_a_time" : "jobs");
    testing::ChildSettings limited;
    limited.file_size_limit = limit;
    const testing::ChildResult result = catalogue(out, jobs, limited);
    EXPECT_EQ(result.exit_code, kExitOutput) << result.describe();
    EXPECT_NE(result.stderr_text.find("File too large"), std::string::npos) << result.stderr_text;

    EXPECT_GT(fs::file_size(out / "a_small.mp4"), 1000u);
    EXPECT_TRUE(fs::is_regular_file(out / "a_small.png"));
    EXPECT_FALSE(fs::exists(out / "b_bounce.mp4"));
    EXPECT_FALSE(fs::exists(out / "b_bounce.png")) << "a poster without its video";
    for (const auto& entry : fs::directory_iterator(out))
      EXPECT_NE(entry.path().extension(), ".part") << "left behind: " << entry.path();

    const std::string page = contents(out / "index.html");
    EXPECT_NE(page.find("<source src=\"a_small.mp4\""), std::string::npos) << page;
    EXPECT_NE(page.find("b_bounce: not rendered"), std::string::npos) << page;
    EXPECT_NE(page.find("(exit code 3: the output cannot be written)"), std::string::npos) << page;
    EXPECT_EQ(page.find("b_bounce.mp4"), std::string::npos) << page;
  }
}

}  // namespace
}  // namespace impulse
