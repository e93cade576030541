// `impulse export`: a scene's page, opened from disk in a real headless Chromium with WebGL. The
// page draws each body where the trace of the same run puts it, fetches nothing, and reports no
// error.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/child_process.h"
#include "tests/support/scene_scratch.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

// A body's pose at a moment: x y z and the quaternion w x y z.
using Pose = std::vector<double>;
using Poses = std::map<std::pair<std::string, long>, Pose>;  // (body, moment in ms) -> pose

// `impulse simulate --trace`'s rows at the given moments (ms), by body name.
Poses traced(const fs::path& csv, const std::vector<long>& moments) {
  Poses poses;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    const long ms = std::lround(std::stod(cells[0]) * 1000);
    for (const long moment : moments)
      if (ms == moment) poses[{cells[2], ms}] = {std::stod(cells[3]), std::stod(cells[4]), std::stod(cells[5]), std::stod(cells[6]),
                                                   std::stod(cells[7]), std::stod(cells[8]), std::stod(cells[9])};
  }
  return poses;
}

// What the page drew: its probe's POSE lines (t x y z qw qx qy qz name), and its errors.
struct Drawn {
  Poses poses;
  std::string errors;
  bool gl = false;
};
Drawn opened(const fs::path& page, const fs::path& dir, const std::string& moments) {
  const testing::ChildResult browser = testing::run_child(
      {"/bin/sh", "-c",
       "timeout 120 chromium --headless --no-sandbox --disable-gpu --user-data-dir='" + (dir / "profile").string() +
           "' --virtual-time-budget=10000 --dump-dom 'file://" + page.string() + "#probe=" + moments + "' > '" +
           (dir / "dom.html").string() + "'"});
  EXPECT_TRUE(browser.succeeded()) << browser.describe();
  const std::string dom = contents(dir / "dom.html");
  Drawn drawn;
  auto between = [&](const std::string& open) {
    const size_t from = dom.find(open);
    if (from == std::string::npos) return std::string();
    const size_t start = from + open.size(), end = dom.find("</pre>", start);
    return end == std::string::npos ? std::string() : dom.substr(start, end - start);
  };
  drawn.errors = between("<pre id=\"errors\">");
  std::istringstream probe(between("<pre id=\"probe\">"));
  std::string line;
  while (std::getline(probe, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "GL") {
      std::string yes;
      words >> yes;
      drawn.gl = yes == "yes";
      continue;
    }
    if (kind != "POSE") continue;
    double t;
    Pose pose(7);
    words >> t;
    for (double& v : pose) words >> v;
    std::string name;
    std::getline(words >> std::ws, name);
    drawn.poses[{name, std::lround(t * 1000)}] = pose;
  }
  return drawn;
}

// Every moving body of the scene, at each moment, where the trace of the same run has it: its
// centre within 1e-4 m, its orientation within 1e-4 (either sign of the quaternion).
void expect_page_draws_the_trace(const std::string& scene, const std::vector<long>& moments_ms) {
  SCOPED_TRACE(scene);
  const fs::path dir = testing::scratch("page_test", fs::path(scene).stem().string());
  const fs::path page = dir / "page.html", trace = dir / "trace.csv";
  const std::string source = std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/" + scene;
  const testing::ChildResult exported = testing::run_child({IMPULSE_PROGRAM, "-q", "export", source, "-o", page.string()});
  ASSERT_TRUE(exported.succeeded()) << exported.describe();
  const testing::ChildResult simulated = testing::run_child({IMPULSE_PROGRAM, "-q", "simulate", source, "--trace", trace.string()});
  ASSERT_TRUE(simulated.succeeded()) << simulated.describe();

  const std::string html = contents(page);
  EXPECT_LT(html.size(), 2u << 20) << "bytes: a catalogue scene's page under 2 MB";
  for (const char* fetch : {"<script src", "<link", "<img", "import(", "fetch("})
    EXPECT_EQ(html.find(fetch), std::string::npos) << "the page fetches nothing: " << fetch;

  std::ostringstream moments;
  for (size_t i = 0; i < moments_ms.size(); ++i) moments << (i > 0 ? "," : "") << moments_ms[i] / 1000.0;
  const Drawn drawn = opened(page, dir, moments.str());
  EXPECT_TRUE(drawn.gl) << "WebGL";
  EXPECT_EQ(drawn.errors, "");
  const Poses expected = traced(trace, moments_ms);
  ASSERT_FALSE(expected.empty());
  int compared = 0;
  for (const auto& [key, pose] : expected) {
    const auto found = drawn.poses.find(key);
    if (found == drawn.poses.end()) continue;  // a plane: drawn, not posed
    ++compared;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(found->second[k], pose[k], 1e-4) << key.first << " at " << key.second << " ms";
    double dot = 0;
    for (int k = 3; k < 7; ++k) dot += found->second[k] * pose[k];
    EXPECT_NEAR(std::abs(dot), 1, 1e-4) << key.first << " at " << key.second << " ms: its orientation";
  }
  EXPECT_GE(compared, int(moments_ms.size())) << "bodies compared";
}

TEST(Page, TheBallsDrawnWhereTheTraceHasThem) { expect_page_draws_the_trace("bounce.toml", {0, 500, 1500}); }

TEST(Page, HullsCylindersAndAMeshDrawnWhereTheTraceHasThem) {
  expect_page_draws_the_trace("s5_hulls.toml", {1000, 2500});
  expect_page_draws_the_trace("s5_half_pipe.toml", {1000, 2500});
}

// A scene that cannot be read writes no page, and says where it is wrong.
TEST(Page, ABadSceneWritesNothing) {
  const fs::path dir = testing::scratch("page_test", "bad");
  std::ofstream(dir / "bad.toml") << "[[body]]\nshape = \"mesh\"\nfile = \"nowhere.obj\"\n";
  const testing::ChildResult exported =
      testing::run_child({IMPULSE_PROGRAM, "-q", "export", (dir / "bad.toml").string(), "-o", (dir / "bad.html").string()});
  EXPECT_EQ(exported.exit_code, 1) << exported.describe();
  EXPECT_NE(exported.stderr_text.find("bad.toml:3: [[body]] 'body 1' field 'file': no file"), std::string::npos) << exported.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "bad.html"));
}

}  // namespace
}  // namespace impulse
