// Several renders into one output path at once (a course's `make -j`, two terminals): each writes
// its own temporary beside the output and renames it over the output when complete, so the output
// is always one complete video, every writer reports success truthfully, and no temporary is
// left. A temporary whose writer was killed is removed by a later render into its directory.
#include <sys/file.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/child_process.h"
#include "tests/support/video_decode.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

class OutputConcurrency : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = fs::temp_directory_path() / ("impulse_output_concurrency_" + std::to_string(getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(work_);
    fs::create_directories(work_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(work_);
  }

  // A short render (the catalogue's bounce, its first second, at low quality) into `output`.
  static std::vector<std::string> render_arguments(const fs::path& output) {
    return {IMPULSE_PROGRAM, "-q", "render", "assets/scenes/bounce.toml", "--quality", "low",
            "--set", "scene.duration=1", "-o", output.string()};
  }
  static testing::ChildSettings in_source() {
    testing::ChildSettings settings;
    settings.working_directory = IMPULSE_SOURCE_DIR;
    return settings;
  }
  std::vector<std::string> temporaries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(work_))
      if (entry.path().extension() == ".part") names.push_back(entry.path().filename().string());
    return names;
  }

  fs::path work_;
};

TEST_F(OutputConcurrency, TwoOrFourWritersIntoOnePathLeaveOneCompleteVideoEveryRound) {
  const fs::path video = work_ / "same.mp4";
  const testing::ChildResult alone = testing::run_child(render_arguments(video), in_source());
  ASSERT_TRUE(alone.succeeded()) << alone.describe();
  const size_t frame_count = testing::decode_video(video.string()).frames.size();
  ASSERT_GT(frame_count, 10u);

  constexpr int kRounds = 20;
  for (const int writers : {2, 4}) {
    for (int round = 0; round < kRounds; ++round) {
      std::vector<std::unique_ptr<testing::ChildProcess>> children;
      for (int i = 0; i < writers; ++i)
        children.push_back(std::make_unique<testing::ChildProcess>(render_arguments(video), in_source()));
      for (auto& child : children) {
        const testing::ChildResult result = child->wait();
        EXPECT_TRUE(result.succeeded()) << writers << " writers, round " << round << ": " << result.describe();
      }
      const testing::DecodedVideo decoded = testing::decode_video(video.string());
      ASSERT_EQ(decoded.frames.size(), frame_count) << writers << " writers, round " << round;
      ASSERT_TRUE(temporaries().empty()) << temporaries().front();
    }
  }
}

// A process id that no process has: a child that has exited and been reaped.
pid_t dead_process_id() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  return child;
}

TEST_F(OutputConcurrency, ALaterRenderRemovesTheTemporariesOfDeadWritersAndNoOthers) {
  const pid_t dead = dead_process_id();
  const fs::path of_dead_writer = work_ / ("old.mp4." + std::to_string(dead) + "-0.part");
  const fs::path still_locked = work_ / ("held.mp4." + std::to_string(dead) + "-1.part");  // its lock says a writer lives
  const fs::path of_live_writer = work_ / ("live.mp4." + std::to_string(getpid()) + "-0.part");
  const fs::path not_ours = work_ / "notes.part";
  const fs::path old_style = work_ / "legacy.mp4.part";
  for (const fs::path& path : {of_dead_writer, still_locked, of_live_writer, not_ours, old_style})
    std::ofstream(path) << "half a video\n";
  const int lock = open(still_locked.c_str(), O_RDONLY);
  ASSERT_GE(lock, 0);
  ASSERT_EQ(flock(lock, LOCK_EX), 0);

  const testing::ChildResult result = testing::run_child(render_arguments(work_ / "new.mp4"), in_source());
  close(lock);
  ASSERT_TRUE(result.succeeded()) << result.describe();
  EXPECT_TRUE(fs::exists(work_ / "new.mp4"));
  EXPECT_FALSE(fs::exists(of_dead_writer));
  EXPECT_TRUE(fs::exists(still_locked));
  EXPECT_TRUE(fs::exists(of_live_writer));
  EXPECT_TRUE(fs::exists(not_ours));
  EXPECT_TRUE(fs::exists(old_style));
}

}  // namespace
}  // namespace impulse
