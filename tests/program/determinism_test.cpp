// The program's outputs are reproducible: the same trace whatever the solver's threads, the same
// MP4 bytes run after run.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

// The same scene gives the same trace with the solver on one thread or several (eight: more than
// the cores), and the same MP4 bytes run after run.
TEST(Determinism, TracesWhateverTheThreadsAndVideosRunToRun) {
  const fs::path dir = work_directory();
  const fs::path scene = fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/ex3_stacks.toml";
  for (const char* threads : {"1", "2", "3", "8"}) {
    const testing::ProgramRun result =
        run_in_process({"simulate", scene.string(), "--duration", "2", "--set", std::string("world.threads=") + threads,
                 "--trace", (dir / (std::string("threads_") + threads + ".csv")).string()});
    ASSERT_TRUE(result.succeeded()) << result.describe();
  }
  for (const char* threads : {"2", "3", "8"})
    EXPECT_EQ(contents(dir / "threads_1.csv"), contents(dir / (std::string("threads_") + threads + ".csv"))) << threads << " threads";
  EXPECT_GT(contents(dir / "threads_1.csv").size(), 100000u);

  std::ofstream(dir / "slide.toml") << std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  for (const char* run : {"a", "b"}) {
    const testing::ProgramRun result = run_in_process(
        {"-q", "render", (dir / "slide.toml").string(), "-o", (dir / (std::string(run) + ".mp4")).string()});
    ASSERT_TRUE(result.succeeded()) << result.describe();
  }
  EXPECT_EQ(contents(dir / "a.mp4"), contents(dir / "b.mp4"));
  EXPECT_GT(contents(dir / "a.mp4").size(), 1000u);
}

}  // namespace
}  // namespace impulse
