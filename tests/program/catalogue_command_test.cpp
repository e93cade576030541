// `impulse catalogue`: --shard, --changed-only, and --jobs rendering every scene once, as one at a
// time would.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include "tests/support/child_process.h"

#include <chrono>

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

// catalogue --shard K/N renders every Nth scene from the Kth; --changed-only keeps a video newer
// than its scene file, and renders it again once the scene file changes.
TEST(Catalogue, ShardsAndChangedOnly) {
  const fs::path dir = work_directory();
  fs::create_directories(dir / "scenes");
  const std::string small = std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  for (const char* name : {"a.toml", "b.toml", "c.toml"}) std::ofstream(dir / "scenes" / name) << small;
  const std::string scenes = (dir / "scenes").string(), out = (dir / "out").string();
  const testing::ProgramRun second = run_in_process({"-q", "catalogue", "--scenes", scenes, "-o", out, "--shard", "2/2"});
  ASSERT_TRUE(second.succeeded()) << second.describe();
  EXPECT_FALSE(fs::exists(dir / "out" / "a.mp4"));
  EXPECT_TRUE(fs::exists(dir / "out" / "b.mp4"));
  EXPECT_FALSE(fs::exists(dir / "out" / "c.mp4"));
  EXPECT_EQ(run_in_process({"-q", "catalogue", "--scenes", scenes, "-o", out, "--shard", "3/2"}).exit_code, 1);

  const testing::ProgramRun first = run_in_process({"-q", "catalogue", "--scenes", scenes, "-o", out, "--changed-only"});
  ASSERT_TRUE(first.succeeded()) << first.describe();
  EXPECT_NE(first.stderr_text.find("b.toml: unchanged, kept"), std::string::npos) << first.stderr_text;
  EXPECT_NE(first.stderr_text.find("rendered 2 of 3 scenes"), std::string::npos) << first.stderr_text;
  fs::last_write_time(dir / "scenes" / "b.toml", fs::file_time_type::clock::now() + std::chrono::seconds(5));
  const testing::ProgramRun again = run_in_process({"-q", "catalogue", "--scenes", scenes, "-o", out, "--changed-only"});
  ASSERT_TRUE(again.succeeded()) << again.describe();
  EXPECT_NE(again.stderr_text.find("rendered 1 of 3 scenes"), std::string::npos) << again.stderr_text;
  EXPECT_EQ(again.stderr_text.find("b.toml: unchanged"), std::string::npos) << again.stderr_text;
}

// --jobs starts /proc/self/exe: the program itself, in a child process.
ChildResult impulse(const std::vector<std::string>& arguments) {
  std::vector<std::string> argv = {IMPULSE_PROGRAM};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run_child(argv);
}

// --jobs 2 renders every scene once, each in a child process of its own, the same bytes as one at
// a time, and writes one gallery.
TEST(Catalogue, JobsRenderEverySceneOnceAsOneAtATimeWould) {
  const fs::path dir = work_directory();
  fs::create_directories(dir / "scenes");
  const std::string small = std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  for (const char* name : {"a.toml", "b.toml", "c.toml"}) std::ofstream(dir / "scenes" / name) << small;
  const std::string scenes = (dir / "scenes").string();
  const testing::ChildResult jobs = impulse({"catalogue", "--scenes", scenes, "-o", (dir / "jobs").string(), "--jobs", "2"});
  ASSERT_TRUE(jobs.succeeded()) << jobs.describe();
  const testing::ChildResult alone = impulse({"-q", "catalogue", "--scenes", scenes, "-o", (dir / "alone").string()});
  ASSERT_TRUE(alone.succeeded()) << alone.describe();
  for (const char* name : {"a", "b", "c"}) {
    EXPECT_NE(jobs.stderr_text.find(std::string(name) + ".toml: done in"), std::string::npos) << jobs.stderr_text;
    const std::string video = std::string(name) + ".mp4";
    EXPECT_GT(fs::file_size(dir / "jobs" / video), 1000u);
    EXPECT_EQ(contents(dir / "jobs" / video), contents(dir / "alone" / video)) << video;
  }
  EXPECT_NE(jobs.stderr_text.find("rendered 3 of 3 scenes"), std::string::npos) << jobs.stderr_text;
  EXPECT_TRUE(fs::exists(dir / "jobs" / "index.html"));
  EXPECT_EQ(impulse({"catalogue", "--scenes", scenes, "-o", (dir / "jobs").string(), "--jobs", "0"}).exit_code, 1);
}

}  // namespace
}  // namespace impulse
