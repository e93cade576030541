// The command line a student and a course's CI use, run as a program: --set changes what the
// trace shows and is refused naming itself; `simulate` writes numbers that obey the physics;
// options work after the subcommand.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "demos/film/film.h"
#include "tests/child_process.h"
#include "tests/scene_scratch.h"
#include "tests/video_decode.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

fs::path work_directory() {
  const fs::path dir = fs::temp_directory_path() / ("impulse_program_cli_" + std::to_string(getpid()) + "_" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

testing::ChildResult impulse(const std::vector<std::string>& arguments) {
  std::vector<std::string> argv = {IMPULSE_PROGRAM};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return testing::run_child(argv);
}

// A CSV file as rows of named columns.
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(file, line)) {
    std::map<std::string, std::string> row;
    std::stringstream cells(line);
    std::string cell;
    for (size_t i = 0; i < header.size() && std::getline(cells, cell, ','); ++i) row[header[i]] = cell;
    rows.push_back(row);
  }
  return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
  return std::stod(row.at(column));
}

// The last row of `body` in a --trace file.
std::map<std::string, std::string> last_of(const std::vector<std::map<std::string, std::string>>& rows,
                                           const std::string& body) {
  std::map<std::string, std::string> last;
  for (const auto& row : rows)
    if (row.at("body") == "\"" + body + "\"") last = row;
  return last;
}

// Two spheres head on in empty space: 1 kg at 3 m/s onto 2 kg at rest, e = 1.
constexpr const char* kHeadOn = R"(
[scene]
duration = 2.0
[world]
gravity = [0, 0, 0]
[[body]]
name = "light"
shape = "sphere"
radius = 0.5
mass = 1.0
restitution = 1.0
position = [-2, 0, 0]
velocity = [3, 0, 0]
[[body]]
name = "heavy"
shape = "sphere"
radius = 0.5
mass = 2.0
restitution = 1.0
position = [1, 0, 0]
)";

TEST(Simulate, AHeadOnHitKeepsMomentumAndExchangesItAsEquationEightSays) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "head_on.toml") << kHeadOn;
  const testing::ChildResult result = impulse({"simulate", (dir / "head_on.toml").string(), "--trace",
                                               (dir / "bodies.csv").string(), "--world", (dir / "world.csv").string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();

  const auto world = read_csv(dir / "world.csv");
  ASSERT_EQ(world.size(), 121u);  // the start, then 2 s at 60 steps a second
  for (const auto& row : world) EXPECT_NEAR(number(row, "px_kg_m_per_s"), 3.0, 1e-9) << "step " << row.at("step");
  // Elastic: v1' = (m1 - m2) / (m1 + m2) v1 = -1 m/s, v2' = 2 m1 / (m1 + m2) v1 = 2 m/s.
  const auto bodies = read_csv(dir / "bodies.csv");
  EXPECT_NEAR(number(last_of(bodies, "light"), "vx_m_per_s"), -1.0, 1e-3);
  EXPECT_NEAR(number(last_of(bodies, "heavy"), "vx_m_per_s"), 2.0, 1e-3);
  // The trace begins with the starting state, at step 0, as the scene file gives it.
  EXPECT_EQ(bodies.front().at("body"), "\"light\"");
  EXPECT_EQ(number(bodies.front(), "time_s"), 0.0);
  EXPECT_EQ(number(bodies.front(), "step"), 0.0);
  EXPECT_EQ(number(bodies.front(), "x_m"), -2.0);
  EXPECT_EQ(number(bodies.front(), "vx_m_per_s"), 3.0);
  EXPECT_EQ(number(world.front(), "time_s"), 0.0);
  EXPECT_EQ(number(world.front(), "kinetic_energy_J"), 4.5);
  EXPECT_NEAR(number(world[1], "time_s"), 1.0 / 60, 1e-9);
}

// A box sliding on the ground: friction stops it; --set world.friction=false lets it slide on.
constexpr const char* kSlide = R"(
[scene]
duration = 2.0
[[body]]
name = "ground"
shape = "plane"
friction = 0.5
[[body]]
name = "box"
shape = "box"
size = [1, 1, 1]
position = [0, 0.5, 0]
velocity = [3, 0, 0]
friction = 0.5
)";

TEST(Set, FrictionOffChangesWhatTheTraceShows) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  const std::string scene = (dir / "slide.toml").string();
  ASSERT_TRUE(impulse({"simulate", scene, "--trace", (dir / "with.csv").string()}).succeeded());
  const testing::ChildResult without =
      impulse({"simulate", scene, "--set", "world.friction=false", "--trace", (dir / "without.csv").string()});
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
    const testing::ChildResult result = impulse({"check", scene, "--set", each.setting});
    EXPECT_EQ(result.exit_code, 1) << each.setting;
    EXPECT_NE(result.stderr_text.find(each.says), std::string::npos) << result.stderr_text;
  }
}

TEST(Cli, OptionsWorkAfterTheSubcommandAndHelpShowsExamplesAndExitCodes) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  EXPECT_TRUE(impulse({"check", (dir / "slide.toml").string(), "-q"}).succeeded());
  for (const char* command : {"render", "compare", "simulate", "check", "verify", "catalogue"}) {
    const testing::ChildResult help = impulse({command, "--help"});
    EXPECT_TRUE(help.succeeded()) << command;
  }
}

// The video records the settings that changed it, in its comment tag.
TEST(Set, TheVideoRecordsTheSettings) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  const fs::path video = dir / "slide.mp4";
  const testing::ChildResult result = impulse(
      {"-q", "render", (dir / "slide.toml").string(), "--set", "world.friction=false", "-o", video.string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();
  EXPECT_EQ(testing::decode_video(video.string()).comment, "--set world.friction=false");
}

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
  const testing::ChildResult checked = impulse({"check", "--simulate", (dir / "checked.toml").string()});
  EXPECT_EQ(checked.exit_code, 2) << checked.describe();
  EXPECT_NE(checked.stderr_text.find("pass [[check]] 1 (momentum): changed by"), std::string::npos) << checked.stderr_text;
  EXPECT_NE(checked.stderr_text.find("FAIL [[check]] 2 (at_rest of 'light'): fastest 1 m/s (below 0.01)"),
            std::string::npos)
      << checked.stderr_text;
  const testing::ChildResult rendered =
      impulse({"-q", "render", (dir / "checked.toml").string(), "-o", (dir / "checked.mp4").string()});
  EXPECT_EQ(rendered.exit_code, 2) << rendered.describe();
  EXPECT_TRUE(fs::exists(dir / "checked.mp4"));
  const testing::ChildResult fixed = impulse(
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
  const testing::ChildResult checked = impulse({"check", (dir / "bad_tex.toml").string()});
  EXPECT_EQ(checked.exit_code, 1) << checked.describe();
  EXPECT_NE(checked.stderr_text.find(expected), std::string::npos) << checked.stderr_text;
  const testing::ChildResult rendered =
      impulse({"-q", "render", (dir / "bad_tex.toml").string(), "-o", (dir / "bad_tex.mp4").string()});
  EXPECT_EQ(rendered.exit_code, 1) << rendered.describe();
  EXPECT_NE(rendered.stderr_text.find(expected), std::string::npos) << rendered.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "bad_tex.mp4"));
}

// Two balls dropped side by side; `compare` varies the right one's restitution.
constexpr const char* kTwoBalls = R"(
[scene]
title = "Restitution"
duration = 1.5
[camera]
position = [0, 1.0, 4.5]
target = [0, 0.8, 0]
[video]
width = 960
height = 540
fps = 20
crf = 10
[overlay]
label = "none"
[[body]]
name = "ground"
shape = "plane"
[[body]]
name = "steady"
shape = "sphere"
radius = 0.3
mass = 1.0
restitution = 0.0
position = [-1.2, 1.5, 0]
[[body]]
name = "varied"
shape = "sphere"
radius = 0.3
mass = 1.0
restitution = 0.5
position = [1.2, 1.5, 0]
)";

// Pixels of one half of two panes (above the label) more than 40 levels apart in a channel.
int differing_pixels(const render::Frame& frame, const demos::PaneLayout& layout, bool right_half) {
  int count = 0;
  const int x0 = right_half ? layout.width / 2 : 0;
  for (int y = 0; y < layout.height * 4 / 5; ++y) {
    for (int x = x0; x < x0 + layout.width / 2; ++x) {
      const testing::Rgb a = testing::pixel(frame, layout.origins[0].x() + x, layout.origins[0].y() + y);
      const testing::Rgb b = testing::pixel(frame, layout.origins[1].x() + x, layout.origins[1].y() + y);
      count += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 40;
    }
  }
  return count;
}

// compare: one video, a pane per value, decoded back. The panes differ where the setting acts (the
// right ball: near rest at e = 0.1, high at e = 0.9) and agree where it does not (the left ball,
// the ground), at the same simulated moments. The left ball's impulse arrow has one length in
// both panes: the arrows share a scale (with a scale per pane it would be 1.7 times longer at
// e = 0.1, where the right ball's landing is the smaller impulse).
TEST(Compare, PanesDifferWhereTheSettingDiffersAndAgreeWhereItDoesNot) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "balls.toml") << kTwoBalls;
  const fs::path video = dir / "balls.mp4";
  const testing::ChildResult result = impulse({"-q", "compare", (dir / "balls.toml").string(), "--vary",
                                               "body[varied].restitution=0.1, 0.9", "-o", video.string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();
  const testing::DecodedVideo decoded = testing::decode_video(video.string());
  ASSERT_EQ(decoded.width, 960);
  ASSERT_EQ(decoded.height, 540);
  ASSERT_EQ(decoded.frames.size(), 30u);
  EXPECT_EQ(decoded.comment, "pane 1: --set body[varied].restitution=0.1; pane 2: --set body[varied].restitution=0.9");
  const demos::PaneLayout layout = demos::pane_layout(2, 960, 540, false);
  // 0.55 s: both balls just bounced, their arrows drawn; 0.95 s: the bouncy one near its top.
  for (const int frame : {11, 19}) {
    EXPECT_LT(differing_pixels(decoded.frames[frame], layout, false), 20) << "frame " << frame;
    EXPECT_GT(differing_pixels(decoded.frames[frame], layout, true), 150) << "frame " << frame;
  }
  // Before the first bounce the worlds are the same.
  EXPECT_LT(differing_pixels(decoded.frames[5], layout, true), 20);
}

TEST(Compare, ABadVaryIsRefusedSayingWhy) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "balls.toml") << kTwoBalls;
  const std::string scene = (dir / "balls.toml").string(), video = (dir / "x.mp4").string();
  const testing::ChildResult shared = impulse({"-q", "compare", scene, "--vary", "video.fps=10,20", "-o", video});
  EXPECT_EQ(shared.exit_code, 1) << shared.describe();
  EXPECT_NE(shared.stderr_text.find("every pane of a comparison has the same video"), std::string::npos)
      << shared.stderr_text;
  const testing::ChildResult one = impulse({"-q", "compare", scene, "--vary", "world.friction=false", "-o", video});
  EXPECT_EQ(one.exit_code, 1) << one.describe();
  EXPECT_NE(one.stderr_text.find("give two to four values"), std::string::npos) << one.stderr_text;
  const testing::ChildResult typo = impulse({"-q", "compare", scene, "--vary", "body[varied].restitutoin=0.1,0.9", "-o", video});
  EXPECT_EQ(typo.exit_code, 1) << typo.describe();
  EXPECT_NE(typo.stderr_text.find("did you mean 'restitution'"), std::string::npos) << typo.stderr_text;
  EXPECT_FALSE(fs::exists(video));
}

// catalogue --shard K/N renders every Nth scene from the Kth; --changed-only keeps a video newer
// than its scene file, and renders it again once the scene file changes.
TEST(Catalogue, ShardsAndChangedOnly) {
  const fs::path dir = work_directory();
  fs::create_directories(dir / "scenes");
  const std::string small = std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  for (const char* name : {"a.toml", "b.toml", "c.toml"}) std::ofstream(dir / "scenes" / name) << small;
  const std::string scenes = (dir / "scenes").string(), out = (dir / "out").string();
  const testing::ChildResult second = impulse({"-q", "catalogue", "--scenes", scenes, "-o", out, "--shard", "2/2"});
  ASSERT_TRUE(second.succeeded()) << second.describe();
  EXPECT_FALSE(fs::exists(dir / "out" / "a.mp4"));
  EXPECT_TRUE(fs::exists(dir / "out" / "b.mp4"));
  EXPECT_FALSE(fs::exists(dir / "out" / "c.mp4"));
  EXPECT_EQ(impulse({"-q", "catalogue", "--scenes", scenes, "-o", out, "--shard", "3/2"}).exit_code, 1);

  const testing::ChildResult first = impulse({"-q", "catalogue", "--scenes", scenes, "-o", out, "--changed-only"});
  ASSERT_TRUE(first.succeeded()) << first.describe();
  EXPECT_NE(first.stderr_text.find("b.toml: unchanged, kept"), std::string::npos) << first.stderr_text;
  EXPECT_NE(first.stderr_text.find("rendered 2 of 3 scenes"), std::string::npos) << first.stderr_text;
  fs::last_write_time(dir / "scenes" / "b.toml", fs::file_time_type::clock::now() + std::chrono::seconds(5));
  const testing::ChildResult again = impulse({"-q", "catalogue", "--scenes", scenes, "-o", out, "--changed-only"});
  ASSERT_TRUE(again.succeeded()) << again.describe();
  EXPECT_NE(again.stderr_text.find("rendered 1 of 3 scenes"), std::string::npos) << again.stderr_text;
  EXPECT_EQ(again.stderr_text.find("b.toml: unchanged"), std::string::npos) << again.stderr_text;
}

std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
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


// The same scene gives the same trace with the solver on one thread or two, and the same MP4
// bytes run after run.
TEST(Determinism, TracesWhateverTheThreadsAndVideosRunToRun) {
  const fs::path dir = work_directory();
  const fs::path scene = fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/ex3_stacks.toml";
  for (const char* threads : {"1", "2"}) {
    const testing::ChildResult result =
        impulse({"simulate", scene.string(), "--duration", "2", "--set", std::string("world.threads=") + threads,
                 "--trace", (dir / (std::string("threads_") + threads + ".csv")).string()});
    ASSERT_TRUE(result.succeeded()) << result.describe();
  }
  EXPECT_EQ(contents(dir / "threads_1.csv"), contents(dir / "threads_2.csv"));
  EXPECT_GT(contents(dir / "threads_1.csv").size(), 100000u);

  std::ofstream(dir / "slide.toml") << std::string(kSlide) + "[video]\nwidth = 160\nheight = 120\nfps = 10\n";
  for (const char* run : {"a", "b"}) {
    const testing::ChildResult result = impulse(
        {"-q", "render", (dir / "slide.toml").string(), "-o", (dir / (std::string(run) + ".mp4")).string()});
    ASSERT_TRUE(result.succeeded()) << result.describe();
  }
  EXPECT_EQ(contents(dir / "a.mp4"), contents(dir / "b.mp4"));
  EXPECT_GT(contents(dir / "a.mp4").size(), 1000u);
}

}  // namespace
}  // namespace impulse
