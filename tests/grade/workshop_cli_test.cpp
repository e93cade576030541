// A student's file through the program, as a student and a course's autograder run it: `impulse
// response`, `impulse grade` (its table, its JSON, its videos, its exit codes), and --response on
// render, compare and simulate, with a crash or an endless loop that ends the run cleanly.
#include "demos/film/film.h"
#include "tests/support/child_process.h"
#include "tests/support/video_decode.h"
#include "tests/support/response_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace impulse::workshop {
namespace {

namespace fs = std::filesystem;

fs::path work_directory() {
  const fs::path dir = fs::path(IMPULSE_TEST_SCRATCH) / ("cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The program run as a shell would, its standard output into `out` (when given).
::impulse::testing::ChildResult impulse(const std::vector<std::string>& arguments, const fs::path& out = {}) {
  std::string command = "exec '" + std::string(IMPULSE_PROGRAM) + "'";
  for (const std::string& argument : arguments) command += " '" + argument + "'";
  if (!out.empty()) command += " > '" + out.string() + "'";
  return ::impulse::testing::run_child({"/bin/sh", "-c", command});
}

std::string fixture(const std::string& name) { return std::string(IMPULSE_SOURCE_DIR) + "/tests/response/responses/" + name; }

// A ball dropped on a box on the ground: one scene file for --response.
fs::path drop_scene(const fs::path& dir, const std::string& world_extra = "") {
  const fs::path path = dir / "drop.toml";
  std::ofstream(path) << "[scene]\nduration = 1.0\n[world]\nmethod = \"workshop\"\n" << world_extra
                      << "[video]\nquality = \"low\"\n"
                         "[[body]]\nname = \"ground\"\nshape = \"plane\"\n"
                         "[[body]]\nname = \"box\"\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1.0\nposition = [0, 0.5, 0]\n"
                         "[[body]]\nname = \"ball\"\nshape = \"sphere\"\nradius = 0.3\nmass = 1.0\nposition = [0.2, 2.0, 0]\n";
  return path;
}

std::string text_of(const fs::path& path) { return test::read(path.string()); }

// How alike two panes of a frame are: the mean absolute difference of their pixels (0..255),
// over all but the bottom strip with the pane's label. Panes that show the same thing differ by
// about 0.5 (the encoder's rounding); a body in another place, by 5 or more.
// A failure video's panes: two, with a plot and a caption (the hint) under them.
demos::PaneLayout failure_video_layout(const render::Frame& frame) { return demos::pane_layout(2, frame.width, frame.height, true, true); }

double pane_difference(const render::Frame& frame) {
  const demos::PaneLayout layout = failure_video_layout(frame);
  double total = 0;
  long count = 0;
  for (int y = 0; y < layout.height * 4 / 5; ++y)
    for (int x = 0; x < layout.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const auto at = [&](int pane) {
          return int(frame.rgba[(size_t(layout.origins[pane].y() + y) * frame.width + layout.origins[pane].x() + x) * 4 + c]);
        };
        total += std::abs(at(0) - at(1));
        ++count;
      }
  return total / double(count);
}

TEST(WorkshopCli, ResponseIncludeDirNamesTheHeadersDirectory) {
  const fs::path dir = work_directory();
  const auto result = impulse({"response", "--include-dir"}, dir / "out.txt");
  ASSERT_TRUE(result.succeeded()) << result.describe();
  std::string path = text_of(dir / "out.txt");
  path.erase(path.find_last_not_of('\n') + 1);
  EXPECT_TRUE(fs::exists(fs::path(path) / "impulse" / "workshop.h")) << path;
}

TEST(WorkshopCli, ResponseShowsTheCompilersErrorsWithTheFilesLines) {
  const auto result = impulse({"response", test::listing("listing1_printed.cpp")});
  EXPECT_EQ(result.exit_code, 1) << result.describe();
  EXPECT_NE(result.stderr_text.find("listing1_printed.cpp:77:"), std::string::npos) << result.stderr_text;
}

TEST(WorkshopCli, ResponseBuildsASharedObjectThatRenderTakes) {
  const fs::path dir = work_directory();
  const auto built = impulse({"response", test::listing("listing1_corrected.cpp"), "-o", (dir / "mine.so").string()});
  ASSERT_TRUE(built.succeeded()) << built.describe();
  const auto run = impulse({"simulate", drop_scene(dir).string(), "--response", (dir / "mine.so").string(), "--world", (dir / "w.csv").string()});
  EXPECT_TRUE(run.succeeded()) << run.describe();
}

TEST(WorkshopCli, GradeTableAndExitCodes) {
  const fs::path dir = work_directory();
  const auto good = impulse({"grade", test::listing("listing1_corrected.cpp")}, dir / "good.txt");
  EXPECT_EQ(good.exit_code, 0) << good.describe();
  EXPECT_NE(text_of(dir / "good.txt").find("13 of 13 cases pass"), std::string::npos) << text_of(dir / "good.txt");
  const auto listing = impulse({"grade", test::listing("listing1.cpp")}, dir / "listing.txt");
  EXPECT_EQ(listing.exit_code, 2) << listing.describe();
  const std::string table = text_of(dir / "listing.txt");
  EXPECT_NE(table.find("2 of 13 cases pass"), std::string::npos) << table;
  EXPECT_NE(table.find("hint      they part at 0.00 m/s"), std::string::npos) << table;
  const auto printed = impulse({"grade", test::listing("listing1_printed.cpp")});
  EXPECT_EQ(printed.exit_code, 1) << printed.describe();
  const auto prefix = impulse({"grade", "reference", "--only", "e0"});
  EXPECT_EQ(prefix.exit_code, 1) << prefix.describe();
}

TEST(WorkshopCli, GradeJsonForMachines) {
  const fs::path dir = work_directory();
  const auto result = impulse({"grade", test::listing("listing1.cpp"), "--json"}, dir / "grade.json");
  EXPECT_EQ(result.exit_code, 2) << result.describe();
  const std::string json = text_of(dir / "grade.json");
  EXPECT_NE(json.find("\"passed\" : 2\n"), std::string::npos) << json;
  EXPECT_NE(json.find("\"failed\" : 11,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"name\" : \"stack\""), std::string::npos) << json;
}

// --video DIR: a video per failed case, the response's pane beside the reference's; where the
// response fails (e = 0 where e = 0.7 is asked), the two panes differ at the end.
TEST(WorkshopCli, GradeVideoShowsAFailedCaseBesideTheReference) {
  const fs::path dir = work_directory();
  const auto result = impulse({"grade", test::listing("listing1.cpp"), "--only", "head_on_equal_e0.7", "--video", (dir / "videos").string()},
                              dir / "table.txt");
  EXPECT_EQ(result.exit_code, 2) << result.describe();
  const ::impulse::testing::DecodedVideo video = ::impulse::testing::decode_video((dir / "videos" / "head_on_equal_e0.7.mp4").string());
  EXPECT_EQ(video.width, 854);
  EXPECT_EQ(video.height, 480);
  ASSERT_GE(video.frames.size(), 10u);
  EXPECT_LT(pane_difference(video.frames.front()), 1.5);  // the same start
  EXPECT_GT(pane_difference(video.frames.back()), 5.0);   // and not the same end
  const auto passing = impulse({"grade", test::listing("listing1_corrected.cpp"), "--video", (dir / "none").string()}, dir / "passing.txt");
  EXPECT_EQ(passing.exit_code, 0) << passing.describe();
  EXPECT_TRUE(!fs::exists(dir / "none") || fs::is_empty(dir / "none"));
}

// A failure video shows the cause: a response without friction fails the bounce with backspin,
// and its video lasts at least 2 s, slows down at the impact (a chapter marks it), plots the
// ball's speed under the panes and writes the hint's first sentence under them, in the frames
// and in the captions track.
TEST(WorkshopCli, AFailureVideoShowsTheCauseSlowedWithItsPlotAndHint) {
  const fs::path dir = work_directory();
  const std::string file = std::string(IMPULSE_SOURCE_DIR) + "/tests/response/responses/no_friction.cpp";
  const auto result = impulse({"grade", file, "--only", "bounce_spin", "--video", (dir / "videos").string()}, dir / "table.txt");
  EXPECT_EQ(result.exit_code, 2) << result.describe();
  const fs::path video_path = dir / "videos" / "bounce_spin.mp4";
  const ::impulse::testing::DecodedVideo video = ::impulse::testing::decode_video(video_path.string());
  ASSERT_GT(video.fps, 0);
  EXPECT_GE(double(video.frames.size()) / video.fps, 2.0);
  EXPECT_NE(text_of(dir / "videos" / "bounce_spin.chapters.vtt").find("Impact at t = "), std::string::npos);
  EXPECT_NE(text_of(dir / "videos" / "bounce_spin.vtt").find("hint: the bounce got no friction: vx and the spin are what they were."),
            std::string::npos);
  const render::Frame& frame = video.frames[video.frames.size() / 2];
  const demos::PaneLayout layout = failure_video_layout(frame);
  ASSERT_GT(layout.plots_row_top, 0);
  auto share = [&](int x0, int x1, int y0, int y1, auto&& wanted) {
    long count = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const uint8_t* p = &frame.rgba[(size_t(y) * frame.width + x) * 4];
        count += wanted(p[0], p[1], p[2]);
      }
    return double(count) / double((x1 - x0) * (y1 - y0));
  };
  // The plot's white panel, in the middle under the panes.
  const int plot_top = int(layout.plots_row_top);
  EXPECT_GT(share(frame.width * 2 / 5, frame.width * 3 / 5, plot_top + 5, plot_top + 40, [](int r, int g, int b) { return r > 245 && g > 245 && b > 245; }), 0.6);
  // The caption's dark box, in the band under the plot.
  EXPECT_GT(share(frame.width / 4, frame.width * 3 / 4, frame.height - 40, frame.height - 20, [](int r, int g, int b) { return r < 90 && g < 90 && b < 90; }), 0.5);
}

// compare --vary world.response=FILE,reference: the corrected listing beside the engine's
// reference shows the same motion, frame by frame (only the labels differ).
TEST(WorkshopCli, CorrectedListingLooksLikeTheReference) {
  const fs::path dir = work_directory();
  const auto result = impulse({"compare", drop_scene(dir).string(), "--vary",
                               "world.response=" + test::listing("listing1_corrected.cpp") + ",reference", "-o", (dir / "both.mp4").string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();
  const ::impulse::testing::DecodedVideo video = ::impulse::testing::decode_video((dir / "both.mp4").string());
  ASSERT_GE(video.frames.size(), 10u);
  for (const render::Frame& frame : video.frames) EXPECT_LT(pane_difference(frame), 1.5);
}

// A response that crashes, or never returns, ends the render with a report naming it, and leaves
// no video and no temporary.
TEST(WorkshopCli, ACrashOrAnEndlessLoopEndsTheRenderCleanly) {
  const fs::path dir = work_directory();
  const fs::path scene = drop_scene(dir);
  // Under AddressSanitizer (the test command's second stage) the student's child would catch its
  // own SIGSEGV, print a report and exit(1); a student's build has no sanitizer and dies by the
  // signal, which is what this asks the child to do too.
  const char* asan = std::getenv("ASAN_OPTIONS");
  const std::string asan_before = asan ? asan : "";
  setenv("ASAN_OPTIONS", (asan_before + ":handle_segv=0:handle_sigbus=0:handle_abort=0").c_str(), 1);
  const auto crash = impulse({"render", scene.string(), "--response", fixture("crash.cpp"), "-o", (dir / "crash.mp4").string()});
  if (asan) setenv("ASAN_OPTIONS", asan_before.c_str(), 1); else unsetenv("ASAN_OPTIONS");
  EXPECT_NE(crash.exit_code, 0) << crash.describe();
  EXPECT_NE(crash.stderr_text.find("crash.cpp: AddCollisionImpulse crashed"), std::string::npos) << crash.stderr_text;
  const auto loop = impulse({"render", scene.string(), "--response", fixture("endless_loop.cpp"), "--time-limit", "0.3", "-o",
                             (dir / "loop.mp4").string()});
  EXPECT_NE(loop.exit_code, 0) << loop.describe();
  EXPECT_NE(loop.stderr_text.find("did not return within 0.3 s"), std::string::npos) << loop.stderr_text;
  for (const auto& entry : fs::directory_iterator(dir)) EXPECT_NE(entry.path().extension(), ".mp4") << entry.path();
  for (const auto& entry : fs::directory_iterator(dir)) EXPECT_NE(entry.path().extension(), ".part") << entry.path();
}

// [world] response = "FILE" is the scene file's directory's; a missing one is the field's error.
TEST(WorkshopCli, ASceneNamesItsResponseBesideItself) {
  const fs::path dir = work_directory();
  fs::copy_file(test::listing("listing1_corrected.cpp"), dir / "mine.cpp");
  const fs::path scene = drop_scene(dir, "response = \"mine.cpp\"\n");
  const auto run = impulse({"simulate", scene.string(), "--world", (dir / "w.csv").string()});
  EXPECT_TRUE(run.succeeded()) << run.describe();
  // A [compare] table's values too: the file's listing beside the reference.
  std::ofstream(drop_scene(dir), std::ios::app) << "[compare]\nvary = \"world.response\"\nvalues = [\"mine.cpp\", \"reference\"]\n";
  const auto compared = impulse({"check", "--simulate", (dir / "drop.toml").string()});
  EXPECT_TRUE(compared.succeeded()) << compared.describe();
  const fs::path missing = drop_scene(dir, "response = \"theirs.cpp\"\n");
  const auto refused = impulse({"check", missing.string()});
  EXPECT_EQ(refused.exit_code, 1) << refused.describe();
  EXPECT_NE(refused.stderr_text.find("drop.toml:5: [world] field 'response'"), std::string::npos) << refused.stderr_text;
  EXPECT_NE(refused.stderr_text.find("theirs.cpp: cannot read the response file"), std::string::npos) << refused.stderr_text;
}

}  // namespace
}  // namespace impulse::workshop
