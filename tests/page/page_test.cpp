// `impulse export`: a scene's page, opened from disk in a real headless Chromium with WebGL. The
// page draws each body where the trace of the same run puts it, fetches nothing, and reports no
// error.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "demos/scene/scene_file.h"
#include "render/camera_view.h"
#include "tests/support/child_process.h"
#include "tests/support/traced_poses.h"
#include "tests/support/scene_scratch.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

using testing::Pose;
using testing::Poses;

// What the page drew: its probe's POSE lines (t x y z qw qx qy qz name), and its errors.
struct Drawn {
  Poses poses;
  std::map<std::pair<std::string, long>, std::pair<double, double>> pixels;  // where each centre falls
  int width = 0, height = 0;  // the view's
  std::string errors;
  bool gl = false;
};
Drawn opened(const fs::path& page, const fs::path& dir, const std::string& moments) {
  const testing::ChildResult browser = testing::run_child(
      {"/bin/sh", "-c",
       "timeout 120 chromium --headless --no-sandbox --disable-gpu --window-size=1000,700 --user-data-dir='" +
           (dir / "profile").string() + "' --virtual-time-budget=10000 --dump-dom 'file://" + page.string() + "#probe=" + moments +
           "&size=854x480' > '" +
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
    if (kind == "VIEW") {
      words >> drawn.width >> drawn.height;
      continue;
    }
    if (kind == "PIXEL") {
      double t, x, y;
      words >> t >> x >> y;
      std::string name;
      std::getline(words >> std::ws, name);
      drawn.pixels[{name, std::lround(t * 1000)}] = {x, y};
      continue;
    }
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

class EveryScene : public ::testing::TestWithParam<std::string> {};

// Each catalogue scene's page, opened from disk at 854 x 480: at a third and two thirds of the
// scene, every body where the trace of the same run puts it (its centre within 1e-4 m, its
// orientation within 1e-4, either sign of the quaternion), and where the video's camera shows it
// (its centre within 2 px of the renderer's projection of the traced centre); no error; WebGL;
// nothing fetched; under 2 MB (the 1001-body heap: 25 MB).
TEST_P(EveryScene, ThePageDrawsEachBodyWhereTheTraceAndTheVideosCameraPutIt) {
  const std::string name = GetParam();
  const fs::path dir = testing::scratch("page_test", name);
  const fs::path page = dir / "page.html", trace = dir / "trace.csv";
  const std::string source = std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/" + name + ".toml";
  const demos::Scene scene = demos::load_scene(source);
  const testing::ChildResult exported = testing::run_child({IMPULSE_PROGRAM, "-q", "export", source, "-o", page.string()});
  ASSERT_TRUE(exported.succeeded()) << exported.describe();
  const testing::ChildResult simulated = testing::run_child({IMPULSE_PROGRAM, "-q", "simulate", source, "--trace", trace.string()});
  ASSERT_TRUE(simulated.succeeded()) << simulated.describe();

  const std::string html = contents(page);
  EXPECT_LT(html.size(), name == "ex2_many_bodies" ? 25u << 20 : 2u << 20) << "bytes";
  for (const char* fetch : {"<script src", "<link", "<img", "import("})
    EXPECT_EQ(html.find(fetch), std::string::npos) << "the page fetches nothing: " << fetch;
  // and may not: its policy allows no source but its own inline script and style (the preview's
  // polling, in the same script, is refused here).
  EXPECT_NE(html.find("content=\"default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'\">"), std::string::npos);

  // Frames that are also steps: a third and two thirds of the way, to the frame.
  const int fps = scene.video.fps;
  std::vector<long> moments_ms;
  std::ostringstream moments;
  for (const int share : {1, 2}) {
    const long frame = std::lround(scene.duration * share / 3 * fps);
    moments_ms.push_back(std::lround(1000.0 * frame / fps));
    moments << (share > 1 ? "," : "") << double(frame) / fps;
  }
  const Drawn drawn = opened(page, dir, moments.str());
  EXPECT_TRUE(drawn.gl) << "WebGL";
  EXPECT_EQ(drawn.errors, "");
  ASSERT_EQ(drawn.width, 854);
  ASSERT_EQ(drawn.height, 480);
  const Poses expected = testing::traced_poses(trace, moments_ms);
  const render::CameraView view = render::make_camera_view({scene.camera.position, scene.camera.target, scene.camera.fov_y_degrees}, 854, 480);
  int compared = 0;
  for (const auto& [key, pose] : expected) {
    const auto found = drawn.poses.find(key);
    if (found == drawn.poses.end()) continue;  // a plane: drawn, not posed
    ++compared;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(found->second[k], pose[k], 1e-4) << key.first << " at " << key.second << " ms";
    double dot = 0;
    for (int k = 3; k < 7; ++k) dot += found->second[k] * pose[k];
    EXPECT_NEAR(std::abs(dot), 1, 1e-4) << key.first << " at " << key.second << " ms: its orientation";
    const auto pixel = view.to_pixels(Eigen::Vector3f(float(pose[0]), float(pose[1]), float(pose[2])));
    const auto seen = drawn.pixels.find(key);
    if (!pixel || seen == drawn.pixels.end()) continue;  // behind the camera
    EXPECT_NEAR(seen->second.first, pixel->x(), 2) << key.first << " at " << key.second << " ms: pixels across";
    EXPECT_NEAR(seen->second.second, pixel->y(), 2) << key.first << " at " << key.second << " ms: pixels down";
  }
  EXPECT_GE(compared, 1) << "bodies compared: the moments are no steps of the trace";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryScene, ::testing::ValuesIn(testing::catalogue_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& scene) { return scene.param; });

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
