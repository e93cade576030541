// The `impulse` program when its output cannot be written or its run is cut short: a clear
// message, the documented exit code (README.md, "The command line"), the previous video under the final
// name untouched, nothing but a regular file ever replaced, and no temporary file left behind.
#include <sys/mount.h>
#include <sys/sysmacros.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "tests/support/child_process.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

constexpr int kExitOutput = 3;
const std::string kPrevious = "the previous video\n";

class OutputFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    work_ = fs::temp_directory_path() / ("impulse_output_faults_" + std::to_string(getpid()) + "_" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(work_);
    fs::create_directories(work_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(work_);
  }

  // `impulse -q render` of a short scene (the catalogue's bounce at low quality) into `output`.
  testing::ChildResult render(const fs::path& output, const testing::ChildSettings& settings = {}) const {
    return testing::run_child(render_arguments(output), with_source(settings));
  }
  std::vector<std::string> render_arguments(const fs::path& output) const {
    return {IMPULSE_PROGRAM, "-q", "render", "assets/scenes/bounce.toml", "--quality", "low", "-o", output.string()};
  }
  static testing::ChildSettings with_source(testing::ChildSettings settings) {
    settings.working_directory = IMPULSE_SOURCE_DIR;
    return settings;
  }
  void write_previous(const fs::path& path) const { std::ofstream(path) << kPrevious; }
  static std::string contents(const fs::path& path) {
    std::ostringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
  }
  // No file anywhere under the work directory ends in .part.
  void expect_no_temporaries() const {
    for (const auto& entry : fs::recursive_directory_iterator(work_)) {
      EXPECT_NE(entry.path().extension(), ".part") << "left behind: " << entry.path();
    }
  }

  fs::path work_;
};

// -o into a folder that is not there yet makes it, as export does.
TEST_F(OutputFaults, MakesTheFolderTheVideoGoesIn) {
  const fs::path video = work_ / "lecture" / "week 3" / "bounce.mp4";
  const testing::ChildResult made = render(video);
  EXPECT_EQ(made.exit_code, 0) << made.describe();
  EXPECT_GT(fs::file_size(video), 1000u);
  expect_no_temporaries();
}

TEST_F(OutputFaults, RefusesToReplaceAnythingButARegularFile) {
  const fs::path fifo = work_ / "fifo.mp4";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  const fs::path directory = work_ / "directory.mp4";
  fs::create_directory(directory);
  const fs::path device = work_ / "null.mp4";  // a node of its own: /dev/null is never put at risk
  const bool have_device = mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;

  struct Case {
    fs::path path;
    const char* says;
    fs::file_type type;
  };
  std::vector<Case> cases = {{fifo, "is a FIFO", fs::file_type::fifo},
                             {directory, "is a directory", fs::file_type::directory}};
  if (have_device) cases.push_back({device, "is a character device", fs::file_type::character});
  for (const Case& each : cases) {
    const testing::ChildResult result = render(each.path);
    EXPECT_EQ(result.exit_code, kExitOutput) << each.path << ": " << result.describe();
    EXPECT_NE(result.stderr_text.find(each.path.string() + " " + each.says), std::string::npos) << result.stderr_text;
    EXPECT_NE(result.stderr_text.find("choose another output path"), std::string::npos) << result.stderr_text;
    EXPECT_EQ(fs::symlink_status(each.path).type(), each.type) << each.path << " was replaced";
  }
  expect_no_temporaries();
}

TEST_F(OutputFaults, WritesThroughALinkToARegularFileAndRefusesADanglingOne) {
  const fs::path target = work_ / "target.mp4";
  write_previous(target);
  const fs::path link = work_ / "link.mp4";
  fs::create_symlink(target, link);
  const testing::ChildResult written = render(link);
  EXPECT_TRUE(written.succeeded()) << written.describe();
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_GT(fs::file_size(target), 1000u);  // the video, through the link

  const fs::path dangling = work_ / "dangling.mp4";
  fs::create_symlink(work_ / "nothing" / "there.mp4", dangling);
  const testing::ChildResult refused = render(dangling);
  EXPECT_EQ(refused.exit_code, kExitOutput) << refused.describe();
  EXPECT_NE(refused.stderr_text.find("symbolic link to nothing"), std::string::npos) << refused.stderr_text;
  EXPECT_TRUE(fs::is_symlink(dangling));
  expect_no_temporaries();
}

TEST_F(OutputFaults, AFileSizeLimitIsAnOutputErrorThatKeepsThePreviousVideo) {
  const fs::path video = work_ / "bounce.mp4";
  write_previous(video);
  testing::ChildSettings settings;
  settings.file_size_limit = 100 * 1024;  // `ulimit -f 100`
  const testing::ChildResult result = render(video, settings);
  EXPECT_EQ(result.exit_code, kExitOutput) << result.describe();
  EXPECT_NE(result.stderr_text.find("File too large"), std::string::npos) << result.stderr_text;
  EXPECT_EQ(contents(video), kPrevious);
  expect_no_temporaries();
}

// A small tmpfs, full during the encode; and the same file system read-only.
TEST_F(OutputFaults, AFullDiskOrAReadOnlyDirectoryIsAnOutputErrorThatKeepsThePreviousVideo) {
  const fs::path disk = work_ / "disk";
  fs::create_directory(disk);
  if (mount("impulse-test", disk.c_str(), "tmpfs", 0, "size=160k") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << "); the file-size limit covers the path";
  }
  const fs::path video = disk / "bounce.mp4";
  write_previous(video);
  const testing::ChildResult full = render(video);
  EXPECT_EQ(full.exit_code, kExitOutput) << full.describe();
  EXPECT_NE(full.stderr_text.find("No space left on device"), std::string::npos) << full.stderr_text;
  EXPECT_EQ(contents(video), kPrevious);
  expect_no_temporaries();

  ASSERT_EQ(mount("impulse-test", disk.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, "size=160k"), 0);
  const testing::ChildResult read_only = render(video);
  EXPECT_EQ(read_only.exit_code, kExitOutput) << read_only.describe();
  EXPECT_NE(read_only.stderr_text.find("Read-only file system"), std::string::npos) << read_only.stderr_text;
  EXPECT_EQ(contents(video), kPrevious);
  // A folder -o names that cannot be made: said so, nothing written.
  const testing::ChildResult no_folder = render(disk / "lecture" / "bounce.mp4");
  EXPECT_EQ(no_folder.exit_code, kExitOutput) << no_folder.describe();
  EXPECT_NE(no_folder.stderr_text.find("cannot make the folder " + (disk / "lecture").string()), std::string::npos) << no_folder.stderr_text;
  EXPECT_NE(no_folder.stderr_text.find("Read-only file system"), std::string::npos) << no_folder.stderr_text;
  EXPECT_EQ(umount(disk.c_str()), 0);
}

// Waits until the temporary of `output` (OUTPUT.PID-N.part) has some bytes in it (the encode is
// under way), at most 60 s.
bool wait_for_temporary(const fs::path& output) {
  const std::string prefix = output.filename().string() + ".";
  for (int i = 0; i < 6000; ++i) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(output.parent_path(), error)) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with(prefix) && name.ends_with(".part") && fs::file_size(entry.path(), error) > 0 && !error)
        return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST_F(OutputFaults, AnInterruptedRenderKeepsThePreviousVideoAndLeavesNoTemporary) {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const fs::path video = work_ / ("bounce_" + std::to_string(signal_number) + ".mp4");
    write_previous(video);
    testing::ChildProcess child(render_arguments(video), with_source({}));
    ASSERT_TRUE(wait_for_temporary(video));
    kill(child.pid(), signal_number);
    const testing::ChildResult result = child.wait();
    EXPECT_EQ(result.signal, signal_number) << result.describe();
    EXPECT_NE(result.stderr_text.find("interrupted"), std::string::npos) << result.stderr_text;
    EXPECT_EQ(contents(video), kPrevious);
  }
  expect_no_temporaries();
}

TEST_F(OutputFaults, AnInterruptedCatalogueKeepsTheVideosItFinished) {
  const fs::path scenes = work_ / "scenes";
  fs::create_directory(scenes);
  for (const char* name : {"a.toml", "b.toml"}) {
    fs::copy_file(fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/bounce.toml", scenes / name);
  }
  const fs::path out = work_ / "out";
  testing::ChildProcess child({IMPULSE_PROGRAM, "-q", "catalogue", "--scenes", scenes.string(), "-o", out.string(),
                               "--quality", "low"},
                              with_source({}));
  ASSERT_TRUE(wait_for_temporary(out / "b.mp4"));
  kill(child.pid(), SIGINT);
  const testing::ChildResult result = child.wait();
  EXPECT_EQ(result.signal, SIGINT) << result.describe();
  EXPECT_GT(fs::file_size(out / "a.mp4"), 1000u);
  EXPECT_FALSE(fs::exists(out / "b.mp4"));
  expect_no_temporaries();
}

// Processes whose command line names `text`: the jobs a catalogue started, if any are left.
int processes_naming(const std::string& text) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream file(entry.path() / "cmdline", std::ios::binary);
    std::string line((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (line.find(text) != std::string::npos && entry.path().filename() != std::to_string(getpid())) ++count;
  }
  return count;
}

// --jobs 2: two scenes render at once, each in a child process; SIGTERM to the catalogue reaches
// both, and neither leaves its .part file or runs on.
TEST_F(OutputFaults, AnInterruptedCatalogueOfJobsStopsEveryJob) {
  const fs::path scenes = work_ / "job_scenes";
  fs::create_directory(scenes);
  for (const char* name : {"a.toml", "b.toml", "c.toml"})
    fs::copy_file(fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/bounce.toml", scenes / name);
  const fs::path out = work_ / "job_out";
  testing::ChildProcess child({IMPULSE_PROGRAM, "catalogue", "--scenes", scenes.string(), "-o", out.string(),
                               "--quality", "low", "--jobs", "2"},
                              with_source({}));
  ASSERT_TRUE(wait_for_temporary(out / "a.mp4"));
  ASSERT_TRUE(wait_for_temporary(out / "b.mp4"));
  EXPECT_EQ(processes_naming(out.string()), 3) << "the catalogue and its two jobs";
  kill(child.pid(), SIGTERM);
  const testing::ChildResult result = child.wait();
  EXPECT_EQ(result.signal, SIGTERM) << result.describe();
  EXPECT_NE(result.stderr_text.find("[1/3] " + (scenes / "a.toml").string() + ": started"), std::string::npos) << result.stderr_text;
  EXPECT_EQ(processes_naming(out.string()), 0);
  expect_no_temporaries();
}

}  // namespace
}  // namespace impulse
