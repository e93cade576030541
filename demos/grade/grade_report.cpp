#include "demos/grade/grade_report.h"

#include "demos/film/render_scene.h"
#include "demos/progress_bar.h"
#include "demos/scene/video_quality.h"

#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace impulse::workshop {

namespace {

constexpr int kTextWidth = 100;  // where a hint is wrapped

// `text` in lines of at most `width` characters after `indent`, broken between words.
std::string wrapped(const std::string& text, size_t width, const std::string& indent) {
  std::istringstream words(text);
  std::string out, line;
  for (std::string word; words >> word;) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n" + indent;
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

// A failed case's video, as a student watches it: the impact in slow motion (an impulse above
// three times what the case's bodies would rest on in a step: the hits and bounces, not a stack's
// load), at least kShortestVideo long, the last moving body's speed plotted under the panes (the
// struck, bounced or top one) and the hint's first sentence, what went wrong, under them (two
// lines: the rest, what to do, is in the table).
constexpr double kShortestVideo = 2;  // s
void failure_video_settings(demos::Scene& scene, const std::string& hint) {
  double resting = 0;  // N s: the weight of every moving body over one step
  for (const physics::BodyDef& body : scene.bodies)
    if (!body.is_static) {
      resting += body.mass * scene.world.gravity.norm() * scene.world.time_step;
      scene.overlay.plot_bodies = {body.name};
    }
  scene.playback.slow_motion_impulse = std::max(3 * resting, 0.05);
  scene.playback.speed = std::min(1.0, scene.duration / kShortestVideo);
  scene.overlay.plots = {demos::PlotKind::speed};
  const size_t sentence = hint.find(". ");
  if (!hint.empty()) scene.captions = {{"hint: " + hint.substr(0, sentence == std::string::npos ? sentence : sentence + 1), 0, 1e9}};
}

int passed_count(const std::vector<CaseResult>& results) {
  int passed = 0;
  for (const CaseResult& result : results) passed += result.passed;
  return passed;
}

}  // namespace

std::string grade_table(const std::string& file, const std::vector<CaseResult>& results) {
  size_t name_width = 4;
  for (const CaseResult& result : results) name_width = std::max(name_width, result.name.size());
  const std::string indent(2 + name_width + 2 + 4 + 2, ' '), label_indent = indent + std::string(10, ' ');
  auto row = [&](const char* label, const std::string& text) {
    return std::string(label) + std::string(10 - std::string(label).size(), ' ') +
           wrapped(text, kTextWidth - label_indent.size(), label_indent) + "\n";
  };
  std::ostringstream table;
  table << "impulse grade " << file << ": " << passed_count(results) << " of " << results.size() << " cases pass\n\n";
  for (const CaseResult& result : results) {
    table << "  " << result.name << std::string(name_width - result.name.size(), ' ') << "  " << (result.passed ? "pass" : "FAIL")
          << "  " << row("law", result.law);
    if (!result.expected.empty()) table << indent << row("expected", result.expected);
    table << indent << row("measured", result.measured);
    if (!result.failure.empty()) table << indent << row("report", result.failure);
    if (!result.passed && !result.hint.empty()) table << indent << row("hint", result.hint);
  }
  return table.str();
}

std::string grade_json(const std::string& file, const std::vector<CaseResult>& results) {
  toml::array cases;
  for (const CaseResult& result : results)
    cases.push_back(toml::table{{"name", result.name},         {"title", result.title},   {"law", result.law},
                                {"expected", result.expected}, {"measured", result.measured}, {"passed", result.passed},
                                {"hint", result.hint},         {"failure", result.failure}});
  const int passed = passed_count(results);
  const toml::table root{{"file", file}, {"passed", passed}, {"failed", int(results.size()) - passed}, {"cases", cases}};
  std::ostringstream json;
  json << toml::json_formatter{root} << "\n";
  return json.str();
}

std::vector<std::string> write_failure_videos(const std::string& directory, const std::string& file,
                                              const physics::OutsideResponseMaker& response, const std::vector<CaseResult>& results,
                                              bool progress) {
  fs::create_directories(directory);
  std::vector<std::string> written;
  for (const CaseResult& result : results) {
    if (result.passed || !result.failure.empty()) continue;
    demos::Scene student = case_scene(result.name), reference = case_scene(result.name);
    student.world.reference_listing = false;
    student.world.response = response;
    for (demos::Scene* scene : {&student, &reference}) {
      scene->video = *demos::quality_preset("low");
      scene->title = "grade: " + result.title;
      failure_video_settings(*scene, result.hint);
    }
    demos::RenderOptions options;
    options.video_path = (fs::path(directory) / (result.name + ".mp4")).string();
    demos::ProgressBar bar(progress, result.name);
    options.progress = [&bar](int done, int total) { bar.update(done, total); };
    demos::render_panes({{&student, "yours: " + fs::path(file).filename().string()}, {&reference, "reference: listing 1 corrected"}},
                        options);
    bar.finish();
    written.push_back(options.video_path);
  }
  return written;
}

}  // namespace impulse::workshop
