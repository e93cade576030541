// `--layout-report` (demos/film/layout_report.h) over the catalogue: every scene rendered at low
// quality, and in its report no two elements overlap, none leaves the frame, none is left out;
// comparisons of two and four panes the same, every pane named in every frame. The report has
// one entry per video frame, with each pane's bodies; it is written whole or not at all.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include "tests/support/scene_scratch.h"
#include "demos/scene/scene_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;
using nlohmann::json;

struct Box {
  long x, y, w, h;
};
Box box_of(const json& item) { return {item.at("x"), item.at("y"), item.at("w"), item.at("h")}; }
bool overlap(const Box& a, const Box& b) { return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h; }
bool inside(const Box& inner, const Box& outer) {
  return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.w <= outer.x + outer.w && inner.y + inner.h <= outer.y + outer.h;
}

// What is wrong with a report's layout, frame by frame: two elements overlapping, an element
// outside the frame, an element left out.
std::vector<std::string> layout_faults(const json& report) {
  const Box frame{0, 0, report.at("width"), report.at("height")};
  std::vector<std::string> faults;
  for (const json& entry : report.at("frames")) {
    const std::string at = "frame " + std::to_string(entry.at("frame").get<int>()) + ": ";
    const json& elements = entry.at("elements");
    for (size_t i = 0; i < elements.size(); ++i) {
      const std::string name = elements[i].at("name");
      if (!inside(box_of(elements[i]), frame)) faults.push_back(at + name + " outside the frame");
      for (size_t j = 0; j < i; ++j)
        if (overlap(box_of(elements[i]), box_of(elements[j])))
          faults.push_back(at + name + " over " + elements[j].at("name").get<std::string>());
    }
    for (const json& dropped : entry.at("dropped")) faults.push_back(at + dropped.get<std::string>() + " left out");
  }
  return faults;
}

json read_report(const fs::path& path) {
  std::ifstream file(path);
  return json::parse(file);  // throws on anything that is not whole JSON
}

// The faults, at most a few, as one message.
std::string first_faults(const std::vector<std::string>& faults) {
  std::string text;
  for (size_t i = 0; i < faults.size() && i < 8; ++i) text += faults[i] + "\n";
  return text;
}

// The check itself fails on an overlap, an element outside the frame and one left out.
TEST(LayoutReport, TheCheckFindsOverlapsElementsOutsideTheFrameAndElementsLeftOut) {
  const json good = json::parse(R"({"width": 854, "height": 480, "frames": [{"frame": 0, "elements": [
      {"name": "title", "x": 13, "y": 13, "w": 300, "h": 36}, {"name": "legend", "x": 13, "y": 53, "w": 200, "h": 70}],
      "dropped": [], "bodies": []}]})");
  EXPECT_TRUE(layout_faults(good).empty());
  json bad = good;
  bad["frames"][0]["elements"][1]["y"] = 40;  // the legend up over the title
  bad["frames"][0]["elements"].push_back({{"name", "clock"}, {"x", 800}, {"y", 13}, {"w", 100}, {"h", 40}});
  bad["frames"][0]["dropped"].push_back("panel 1");
  const std::vector<std::string> faults = layout_faults(bad);
  EXPECT_EQ(faults, (std::vector<std::string>{"frame 0: legend over title", "frame 0: clock outside the frame",
                                              "frame 0: panel 1 left out"}));
}

// Every frame of the report, numbered from 0; each with its bodies in panes 0 .. panes - 1.
void expect_every_frame(const json& report, int panes) {
  const json& frames = report.at("frames");
  ASSERT_GT(frames.size(), 10u);
  std::set<int> panes_seen;
  for (size_t i = 0; i < frames.size(); ++i) {
    ASSERT_EQ(frames[i].at("frame").get<size_t>(), i);
    for (const json& body : frames[i].at("bodies")) {
      panes_seen.insert(body.at("pane").get<int>());
      EXPECT_FALSE(body.at("name").get<std::string>().empty());
    }
  }
  EXPECT_EQ(panes_seen.size(), size_t(panes));
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, NothingCoversAnything) {
  const fs::path dir = work_directory();
  const fs::path scene = fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes" / (GetParam() + ".toml");
  const ProgramRun run = run_in_process({"render", scene.string(), "--quality", "low", "-o", (dir / "video.mp4").string(),
                                         "--layout-report", (dir / "layout.json").string()});
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const json report = read_report(dir / "layout.json");
  EXPECT_EQ(report.at("width"), 854);
  EXPECT_EQ(report.at("height"), 480);
  const std::vector<std::string> faults = layout_faults(report);
  EXPECT_TRUE(faults.empty()) << faults.size() << " faults, the first:\n" << first_faults(faults);
  const size_t compared = demos::load_scene(scene.string()).compare.values.size();  // a [compare]'s panes
  expect_every_frame(report, int(std::max<size_t>(compared, 1)));
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryScene, ::testing::ValuesIn(testing::catalogue_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& scene) { return scene.param; });

TEST(LayoutReport, ComparisonsOfTwoAndFourPanesKeepEveryElementApartAndNameEveryPane) {
  const fs::path dir = work_directory();
  const std::string scene = (fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/bounce.toml").string();
  for (const std::string values : {"0.2,0.8", "0.2,0.5,0.8,1"}) {
    SCOPED_TRACE(values);
    const fs::path report_path = dir / ("layout_" + values + ".json");
    const ProgramRun run = run_in_process({"compare", scene, "--vary", "body[0].restitution=" + values, "--quality", "low",
                                           "-o", (dir / "video.mp4").string(), "--layout-report", report_path.string()});
    ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 2) << run.stderr_text;  // 2: a varied pane's [[check]]
    const json report = read_report(report_path);
    const std::vector<std::string> faults = layout_faults(report);
    EXPECT_TRUE(faults.empty()) << faults.size() << " faults, the first:\n" << first_faults(faults);
    const int panes = int(std::count(values.begin(), values.end(), ',')) + 1;
    expect_every_frame(report, panes);
    // Every frame names every pane (inside it: the painter's own test).
    for (const json& entry : report.at("frames")) {
      int names = 0;
      for (const json& element : entry.at("elements"))
        names += element.at("name").get<std::string>().rfind("pane label ", 0) == 0;
      ASSERT_EQ(names, panes) << "frame " << entry.at("frame");
    }
  }
}

// An unwritable report is refused before any work, with the output error's exit code, and
// nothing is left behind.
TEST(LayoutReport, AReportThatCannotBeWrittenIsRefusedAndLeavesNothing) {
  const fs::path dir = work_directory();
  const std::string scene = (fs::path(IMPULSE_SOURCE_DIR) / "assets/scenes/s1_methods.toml").string();
  const ProgramRun run = run_in_process({"render", scene, "--quality", "low", "-o", (dir / "video.mp4").string(),
                                         "--layout-report", (dir / "missing/layout.json").string()});
  EXPECT_EQ(run.exit_code, 3) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("layout.json"), std::string::npos) << run.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "video.mp4"));
  EXPECT_TRUE(fs::is_empty(dir)) << "no temporary left";
}

}  // namespace
}  // namespace impulse
