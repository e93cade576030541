// `impulse export`: a scene's page, opened from disk in a real headless Chromium with WebGL. The
// page draws each body where the trace of the same run puts it and each mark where the video's film
// does, fetches nothing, and reports no error.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "demos/film/marks.h"
#include "demos/film/scene_film.h"
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
  // The marks as drawn, by moment (ms): arrows (origin, vector), lines (ends), dots (place); each
  // with its colour as "#rrggbb" (sRGB).
  struct Mark {
    std::vector<double> numbers;
    std::string colour;
  };
  std::map<long, std::vector<Mark>> arrows, lines, dots;
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
    if (kind == "ARROW" || kind == "LINE" || kind == "DOT") {
      double t;
      words >> t;
      Drawn::Mark mark;
      mark.numbers.resize(kind == "DOT" ? 3 : 6);
      for (double& v : mark.numbers) words >> v;
      words >> mark.colour;
      (kind == "ARROW" ? drawn.arrows : kind == "LINE" ? drawn.lines : drawn.dots)[std::lround(t * 1000)].push_back(mark);
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

// "#rrggbb" of a colour of the renderer (sRGB 0..1), as the page writes a material's.
std::string hex(const render::Colour& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255)));
  return text;
}
bool same_colour(const std::string& a, const std::string& b) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::stoi(a.substr(1 + 2 * k, 2), nullptr, 16) - std::stoi(b.substr(1 + 2 * k, 2), nullptr, 16)) > 1) return false;
  return true;
}
// Whether `drawn` holds a mark within 1e-3 m of `numbers` in `colour` (a line either way round).
bool holds(const std::vector<Drawn::Mark>& drawn, const std::vector<double>& numbers, const std::string& colour, bool either_way = false) {
  auto near = [&](const Drawn::Mark& mark, bool swapped) {
    for (size_t k = 0; k < numbers.size(); ++k) {
      const size_t at = swapped ? (k + 3) % 6 : k;
      if (std::abs(mark.numbers[at] - numbers[k]) > 1e-3) return false;
    }
    return same_colour(mark.colour, colour);
  };
  return std::any_of(drawn.begin(), drawn.end(), [&](const Drawn::Mark& mark) { return near(mark, false) || (either_way && near(mark, true)); });
}
const std::vector<Drawn::Mark>& at(const std::map<long, std::vector<Drawn::Mark>>& marks, long ms) {
  static const std::vector<Drawn::Mark> none;
  const auto found = marks.find(ms);
  return found == marks.end() ? none : found->second;
}
std::vector<double> numbers_of(const render::Vec3f& a, const render::Vec3f& b) { return {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}; }

class EveryScene : public ::testing::TestWithParam<std::string> {};

// Each catalogue scene's page, opened from disk at 854 x 480: at a third and two thirds of the
// scene, every body where the trace of the same run puts it (its centre within 1e-4 m, its
// orientation within 1e-4, either sign of the quaternion), and where the video's camera shows it
// (its centre within 2 px of the renderer's projection of the traced centre); no error; WebGL;
// nothing fetched; under 2 MB (the 1001-body heap: 25 MB). And the marks the video's film draws at
// those moments (rods, ropes, velocity arrows; at real speed also contact dots and arrows), each
// where the film puts it within 1e-3 m, in its colour.
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

  // The marks, as the video's film draws them at the same moments (its stills): its rods and ropes
  // and velocity arrows; and where the video has no slow motion (which holds contacts on screen by
  // the slowed clock), every arrow and dot too.
  demos::Shots shots;
  shots.video_frames = false;
  for (const int share : {1, 2}) shots.stills.push_back(double(std::lround(scene.duration * share / 3 * fps)) / fps);  // the frames' own
  demos::SceneFilm film(scene, 854, 480, shots);
  const bool real_speed = !(scene.playback.slow_motion_impulse > 0);
  for (int k = 0; k < film.picture_count(); ++k) {
    demos::ScenePicture picture;
    film.next(picture);
    const long ms = std::lround(picture.time * 1000);
    const render::DrawList& list = picture.draw_list;
    for (const render::LineItem& line : list.lines)
      EXPECT_TRUE(holds(at(drawn.lines, ms), numbers_of(line.from, line.to), hex(line.colour), true)) << "a line at " << ms << " ms";
    EXPECT_EQ(at(drawn.lines, ms).size(), list.lines.size()) << "lines at " << ms << " ms";
    int arrows = 0;
    for (const render::ArrowItem& arrow : list.arrows) {
      if (!real_speed && hex(arrow.colour) != hex(demos::mark_colour::velocity)) continue;
      if (arrow.direction.norm() < 1e-6) continue;  // drawn as nothing
      ++arrows;
      EXPECT_TRUE(holds(at(drawn.arrows, ms), numbers_of(arrow.origin, arrow.direction), hex(arrow.colour)))
          << "an arrow at " << ms << " ms from " << arrow.origin.transpose() << " along " << arrow.direction.transpose();
    }
    if (real_speed) {
      EXPECT_EQ(int(at(drawn.arrows, ms).size()), arrows) << "arrows at " << ms << " ms";
      EXPECT_EQ(at(drawn.dots, ms).size(), list.points.size()) << "dots at " << ms << " ms";
      for (const render::PointItem& dot : list.points) {
        const std::vector<double> place{dot.position.x(), dot.position.y(), dot.position.z()};
        EXPECT_TRUE(holds(at(drawn.dots, ms), place, hex(dot.colour))) << "a dot at " << ms << " ms at " << dot.position.transpose();
      }
    }
  }
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
