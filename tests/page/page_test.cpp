// `impulse export`: a scene's page, opened from disk in a real headless Chromium with WebGL. The
// page draws each body where the trace of the same run puts it and each mark where the video's film
// does, fetches nothing, and reports no error.
#include <algorithm>
#include <cstdint>
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
#include "demos/scene/scene_compare.h"
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

// What the page drew in a pane: its probe's POSE lines (t x y z qw qx qy qz name), where each
// centre falls in the pane, and the marks.
struct PaneDrawn {
  Poses poses;
  std::map<std::pair<std::string, long>, std::pair<double, double>> pixels;  // where each centre falls
  // The marks as drawn, by moment (ms): arrows (origin, vector), lines (ends), dots (place); each
  // with its colour as "#rrggbb" (sRGB).
  struct Mark {
    std::vector<double> numbers;
    std::string colour;
  };
  std::map<long, std::vector<Mark>> arrows, lines, dots;
};
// A typeset equation the page shows: where (a corner of pane `pane`, from 1; 0: of the whole view),
// and the FNV-1a hash of its SVG.
struct Equation {
  std::string place;
  int pane = 0;
  uint32_t hash = 0;
};
// A plot's curve as the page drew it: its last point.
struct PlotEnd {
  int plot = 0, curve = 0;
  double time = 0, value = 0;
};
// What the page drew: each pane's, the equations and the plots by moment (ms), its errors.
struct Drawn {
  std::vector<PaneDrawn> panes;
  std::map<long, std::vector<Equation>> equations;
  std::map<long, std::vector<PlotEnd>> plots;
  int width = 0, height = 0;  // a pane's
  std::string errors;
  bool gl = false;
};
using Mark = PaneDrawn::Mark;
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
  size_t pane = 0;
  drawn.panes.resize(1);
  while (std::getline(probe, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "VIEW") {
      words >> drawn.width >> drawn.height;
      continue;
    }
    if (kind == "PANE") {
      words >> pane;
      pane -= 1;
      if (drawn.panes.size() <= pane) drawn.panes.resize(pane + 1);
      continue;
    }
    if (kind == "GL") {
      std::string yes;
      words >> yes;
      drawn.gl = yes == "yes";
      continue;
    }
    double t;
    words >> t;
    const long ms = std::lround(t * 1000);
    if (kind == "EQUATION") {
      Equation equation;
      words >> equation.place >> equation.pane >> equation.hash;
      drawn.equations[ms].push_back(equation);
      continue;
    }
    if (kind == "PLOT") {
      PlotEnd end;
      words >> end.plot >> end.curve >> end.time >> end.value;
      drawn.plots[ms].push_back(end);
      continue;
    }
    PaneDrawn& in = drawn.panes[pane];
    if (kind == "PIXEL") {
      double x, y;
      words >> x >> y;
      std::string name;
      std::getline(words >> std::ws, name);
      in.pixels[{name, ms}] = {x, y};
      continue;
    }
    if (kind == "ARROW" || kind == "LINE" || kind == "DOT") {
      Mark mark;
      mark.numbers.resize(kind == "DOT" ? 3 : 6);
      for (double& v : mark.numbers) words >> v;
      words >> mark.colour;
      (kind == "ARROW" ? in.arrows : kind == "LINE" ? in.lines : in.dots)[ms].push_back(mark);
      continue;
    }
    if (kind != "POSE") continue;
    Pose pose(7);
    for (double& v : pose) words >> v;
    std::string name;
    std::getline(words >> std::ws, name);
    in.poses[{name, ms}] = pose;
  }
  return drawn;
}

uint32_t fnv1a(const std::string& text) {
  uint32_t hash = 0x811c9dc5u;
  for (const unsigned char c : text) hash = (hash ^ c) * 0x01000193u;
  return hash;
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
bool holds(const std::vector<Mark>& drawn, const std::vector<double>& numbers, const std::string& colour, bool either_way = false) {
  auto near = [&](const Mark& mark, bool swapped) {
    for (size_t k = 0; k < numbers.size(); ++k) {
      const size_t at = swapped ? (k + 3) % 6 : k;
      if (std::abs(mark.numbers[at] - numbers[k]) > 1e-3) return false;
    }
    return same_colour(mark.colour, colour);
  };
  return std::any_of(drawn.begin(), drawn.end(), [&](const Mark& mark) { return near(mark, false) || (either_way && near(mark, true)); });
}
const std::vector<Mark>& at(const std::map<long, std::vector<Mark>>& marks, long ms) {
  static const std::vector<Mark> none;
  const auto found = marks.find(ms);
  return found == marks.end() ? none : found->second;
}
std::vector<double> numbers_of(const render::Vec3f& a, const render::Vec3f& b) { return {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}; }

class EveryScene : public ::testing::TestWithParam<std::string> {};

// Each catalogue scene's page, opened from disk with each pane 854 x 480 (a comparison's panes, as
// its video shows them): at a third and two thirds of the scene, every body of every pane where the
// trace of the same run puts it (its centre within 1e-4 m, its orientation within 1e-4, either sign
// of the quaternion), and where the video's camera shows it (its centre within 2 px of the
// renderer's projection of the traced centre); no error; WebGL; nothing fetched; under 2 MB (the
// 1001-body heap: 25 MB; the two 231-box pyramids of ex3_stacks, one falling all the while: 3 MB).
// And what the video's film shows at those moments: the marks (rods, ropes, velocity arrows; at
// real speed also contact dots and arrows), each where the film puts it within 1e-3 m, in its
// colour; each typeset equation, the same SVG in the same corner of the same pane; and each plot's
// curves, drawn to the same moment on the film's points.
TEST_P(EveryScene, ThePageDrawsEachBodyWhereTheTraceAndTheVideosCameraPutIt) {
  const std::string name = GetParam();
  const fs::path dir = testing::scratch("page_test", name);
  const fs::path page = dir / "page.html";
  const std::string source = std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/" + name + ".toml";
  const demos::SceneFile file(source);
  const demos::Scene scene = file.scene({});
  // The panes: the [compare]'s values, each the file with KEY=VALUE set; or the scene alone.
  std::vector<demos::Scene> panes = {scene};
  std::vector<std::string> settings = {""};
  if (!scene.compare.values.empty()) {
    panes = demos::load_variants(file, {}, scene.compare);
    settings.clear();
    for (const std::string& value : scene.compare.values) settings.push_back(scene.compare.key + "=" + value);
  }
  const testing::ChildResult exported = testing::run_child({IMPULSE_PROGRAM, "-q", "export", source, "-o", page.string()});
  ASSERT_TRUE(exported.succeeded()) << exported.describe();

  const std::string html = contents(page);
  EXPECT_LT(html.size(), name == "ex2_many_bodies" ? 25u << 20 : name == "ex3_stacks" ? 3u << 20 : 2u << 20) << "bytes";
  for (const char* fetch : {"<script src", "<link", "<img", "import("})
    EXPECT_EQ(html.find(fetch), std::string::npos) << "the page fetches nothing: " << fetch;
  // and may not: its policy allows no source but its own inline script and style, and images it
  // makes itself (the equations' SVGs); the preview's polling, in the same script, is refused here.
  EXPECT_NE(html.find("content=\"default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; img-src data:\">"),
            std::string::npos);

  // Frames that are also steps: a third and two thirds of the way, to the frame.
  const int fps = scene.video.fps;
  std::vector<long> moments_ms;
  std::ostringstream moments;
  demos::Shots shots;
  shots.video_frames = false;
  for (const int share : {1, 2}) {
    const long frame = std::lround(scene.duration * share / 3 * fps);
    moments_ms.push_back(std::lround(1000.0 * frame / fps));
    moments << (share > 1 ? "," : "") << double(frame) / fps;
    shots.stills.push_back(double(frame) / fps);  // the frames' own
  }
  const Drawn drawn = opened(page, dir, moments.str());
  EXPECT_TRUE(drawn.gl) << "WebGL";
  EXPECT_EQ(drawn.errors, "");
  ASSERT_EQ(drawn.width, 854);
  ASSERT_EQ(drawn.height, 480);
  ASSERT_EQ(drawn.panes.size(), panes.size());

  // The films of the panes, as the video makes them (one arrow scale for all).
  std::vector<const demos::Scene*> scenes;
  for (const demos::Scene& pane : panes) scenes.push_back(&pane);
  const auto films = demos::SceneFilm::together(scenes, 854, 480, shots);
  const bool real_speed = !(scene.playback.slow_motion_impulse > 0);
  const render::CameraView view = render::make_camera_view({scene.camera.position, scene.camera.target, scene.camera.fov_y_degrees}, 854, 480);
  static const char* const places[] = {"corner", "top-left", "top-right", "bottom-left", "bottom-right", "bottom"};
  std::map<long, size_t> equations_seen;
  for (size_t p = 0; p < panes.size(); ++p) {
    SCOPED_TRACE("pane " + std::to_string(p + 1) + " " + settings[p]);
    const PaneDrawn& in = drawn.panes[p];
    const fs::path trace = dir / ("trace_" + std::to_string(p + 1) + ".csv");
    std::vector<std::string> simulate = {IMPULSE_PROGRAM, "-q", "simulate", source, "--trace", trace.string()};
    if (!settings[p].empty()) simulate.insert(simulate.end(), {"--set", settings[p]});
    const testing::ChildResult simulated = testing::run_child(simulate);
    ASSERT_TRUE(simulated.succeeded()) << simulated.describe();
    const Poses expected = testing::traced_poses(trace, moments_ms);
    int compared = 0;
    for (const auto& [key, pose] : expected) {
      const auto found = in.poses.find(key);
      if (found == in.poses.end()) continue;  // a plane: drawn, not posed
      ++compared;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(found->second[k], pose[k], 1e-4) << key.first << " at " << key.second << " ms";
      double dot = 0;
      for (int k = 3; k < 7; ++k) dot += found->second[k] * pose[k];
      EXPECT_NEAR(std::abs(dot), 1, 1e-4) << key.first << " at " << key.second << " ms: its orientation";
      const auto pixel = view.to_pixels(Eigen::Vector3f(float(pose[0]), float(pose[1]), float(pose[2])));
      const auto seen = in.pixels.find(key);
      if (!pixel || seen == in.pixels.end()) continue;  // behind the camera
      EXPECT_NEAR(seen->second.first, pixel->x(), 2) << key.first << " at " << key.second << " ms: pixels across";
      EXPECT_NEAR(seen->second.second, pixel->y(), 2) << key.first << " at " << key.second << " ms: pixels down";
    }
    EXPECT_GE(compared, 1) << "bodies compared: the moments are no steps of the trace";

    // The marks, as the video's film draws them at the same moments (its stills): its rods and
    // ropes and velocity arrows; and where the video has no slow motion (which holds contacts on
    // screen by the slowed clock), every arrow and dot too. Its equations, in every case.
    demos::SceneFilm& film = *films[p];
    for (int k = 0; k < film.picture_count(); ++k) {
      demos::ScenePicture picture;
      film.next(picture);
      const long ms = std::lround(picture.time * 1000);
      const render::DrawList& list = picture.draw_list;
      for (const render::LineItem& line : list.lines)
        EXPECT_TRUE(holds(at(in.lines, ms), numbers_of(line.from, line.to), hex(line.colour), true)) << "a line at " << ms << " ms";
      EXPECT_EQ(at(in.lines, ms).size(), list.lines.size()) << "lines at " << ms << " ms";
      int arrows = 0;
      for (const render::ArrowItem& arrow : list.arrows) {
        if (!real_speed && hex(arrow.colour) != hex(demos::mark_colour::velocity)) continue;
        if (arrow.direction.norm() < 1e-6) continue;  // drawn as nothing
        ++arrows;
        EXPECT_TRUE(holds(at(in.arrows, ms), numbers_of(arrow.origin, arrow.direction), hex(arrow.colour)))
            << "an arrow at " << ms << " ms from " << arrow.origin.transpose() << " along " << arrow.direction.transpose();
      }
      if (real_speed) {
        EXPECT_EQ(int(at(in.arrows, ms).size()), arrows) << "arrows at " << ms << " ms";
        EXPECT_EQ(at(in.dots, ms).size(), list.points.size()) << "dots at " << ms << " ms";
        for (const render::PointItem& dot : list.points) {
          const std::vector<double> place{dot.position.x(), dot.position.y(), dot.position.z()};
          EXPECT_TRUE(holds(at(in.dots, ms), place, hex(dot.colour))) << "a dot at " << ms << " ms at " << dot.position.transpose();
        }
      }
      // Each curve of its plots, to the same moment (the last point the page draws within the
      // whole run's sampling of the film's), on the film's points.
      for (size_t plot = 0; plot < picture.overlay.plots.size(); ++plot)
        for (const render::PlotSeries& series : picture.overlay.plots[plot].series) {
          if (series.points.empty()) continue;
          const auto drawn_at = drawn.plots.find(ms);
          const bool found = drawn_at != drawn.plots.end() &&
                             std::any_of(drawn_at->second.begin(), drawn_at->second.end(), [&](const PlotEnd& end) {
                               // The whole run's points are at most (x_end - x_start) / 1024 apart.
                               const render::Plot& axes = picture.overlay.plots[plot];
                               if (end.plot != int(plot) || end.time > series.points.back().x() + 1e-4 ||
                                   end.time < series.points.back().x() - (axes.x_end - axes.x_start) / 1024 - 1e-4)
                                 return false;
                               return std::any_of(series.points.begin(), series.points.end(), [&](const render::Vec2f& point) {
                                 return std::abs(point.x() - end.time) < 1e-4 && std::abs(point.y() - end.value) < 1e-3 * std::max(1.0, std::abs(end.value));
                               });
                             });
          EXPECT_TRUE(found) << "plot " << picture.overlay.plots[plot].title << " at " << ms << " ms: the film's curve ends at ("
                             << series.points.back().transpose() << ")";
        }
      // Each of the pane's equations: in its corner of this pane, or of the view where every pane
      // shows it alike.
      const auto shown = drawn.equations.find(ms);
      for (const render::OverlayPanel& panel : picture.overlay.panels) {
        if (!panel.math.svg) continue;
        const uint32_t hash = fnv1a(*panel.math.svg);
        const bool found = shown != drawn.equations.end() &&
                           std::any_of(shown->second.begin(), shown->second.end(), [&](const Equation& equation) {
                             return equation.hash == hash && equation.place == places[int(panel.place)] &&
                                    (equation.pane == int(p) + 1 || equation.pane == 0);
                           });
        EXPECT_TRUE(found) << "the equation " << panel.math.tex << " at " << ms << " ms, " << places[int(panel.place)];
        equations_seen[ms] += 1;
      }
    }
  }
  // And none that the video does not show.
  for (const auto& [ms, shown] : drawn.equations)
    EXPECT_LE(shown.size(), equations_seen[ms]) << "equations at " << ms << " ms";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryScene, ::testing::ValuesIn(testing::catalogue_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& scene) { return scene.param; });

// A scene whose video's camera moves (follow, fit, keyframes): the page starts from the video's
// first camera and follows it frame by frame, each body where the video's frame shows it (within
// 2 px at 854 x 480).
TEST(Page, FollowsTheVideosMovingCamera) {
  const std::string bodies =
      "[[body]]\nname = \"ground\"\nshape = \"plane\"\n\n"
      "[[body]]\nname = \"ball\"\nshape = \"sphere\"\nradius = 0.3\nposition = [-4, 2, 0]\nvelocity = [4, 3, 0]\n\n"
      "[[body]]\nname = \"box\"\nshape = \"box\"\nsize = [0.6, 0.6, 0.6]\nposition = [2, 0.3, -1]\n";
  const std::map<std::string, std::string> cameras = {
      {"follow", "[camera]\nposition = [-4, 3, 8]\ntarget = [-4, 1.5, 0]\nfollow = \"ball\"\n"},
      {"fit", "[camera]\nposition = [0, 30, 60]\ntarget = [0, 1, 0]\nfit = true\n"},
      {"keyframes", "[camera]\nposition = [0, 3, 12]\ntarget = [0, 1, 0]\n\n[[camera.keyframe]]\ntime = 1.5\nposition = [6, 4, 8]\ntarget = [1, 1, 0]\n"}};
  for (const auto& [name, camera] : cameras) {
    SCOPED_TRACE(name);
    const fs::path dir = testing::scratch("page_test", "camera_" + name);
    const fs::path source = dir / "scene.toml", page = dir / "page.html";
    std::ofstream(source) << "[scene]\ntitle = \"camera\"\nduration = 2\n\n" << camera << "\n" << bodies;
    const testing::ChildResult exported = testing::run_child({IMPULSE_PROGRAM, "-q", "export", source.string(), "-o", page.string()});
    ASSERT_TRUE(exported.succeeded()) << exported.describe();
    const demos::Scene scene = demos::load_scene(source.string());
    ASSERT_EQ(scene.video.fps, 30);
    const Drawn drawn = opened(page, dir, "0,0.5,1.5");
    EXPECT_EQ(drawn.errors, "");
    ASSERT_EQ(drawn.panes.size(), 1u);
    // The video's frames at those moments (real speed: its frames are k / fps), each with its camera.
    demos::SceneFilm film(scene, 854, 480);
    int compared = 0;
    for (int k = 0; k < film.picture_count(); ++k) {
      demos::ScenePicture picture;
      film.next(picture);
      if (picture.frame != 0 && picture.frame != 15 && picture.frame != 45) continue;
      const long ms = std::lround(picture.frame * 1000.0 / 30);
      const render::CameraView view = render::make_camera_view(picture.draw_list.camera, 854, 480);
      for (const auto& [key, pose] : drawn.panes[0].poses) {
        if (key.second != ms) continue;
        const auto pixel = view.to_pixels(Eigen::Vector3f(float(pose[0]), float(pose[1]), float(pose[2])));
        const auto seen = drawn.panes[0].pixels.find(key);
        ASSERT_TRUE(pixel && seen != drawn.panes[0].pixels.end()) << key.first << " at " << ms << " ms";
        EXPECT_NEAR(seen->second.first, pixel->x(), 2) << key.first << " at " << ms << " ms: pixels across";
        EXPECT_NEAR(seen->second.second, pixel->y(), 2) << key.first << " at " << ms << " ms: pixels down";
        ++compared;
      }
    }
    EXPECT_EQ(compared, 6) << "two bodies at three moments";
  }
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
