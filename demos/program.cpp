#include "demos/program.h"

#include "demos/film/live_equations.h"
#include "demos/gallery.h"
#include "demos/progress_bar.h"
#include "demos/scene/scene_world.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "render/part_file.h"

namespace fs = std::filesystem;

namespace impulse::demos {

Comparison load_comparison(const std::vector<std::string>& scene_paths, const std::string& vary,
                           const VideoOverrides& overrides, demos::RenderOptions& options) {
  Comparison comparison;
  std::vector<std::string> labels;
  if (scene_paths.size() == 1) {
    const std::string& path = scene_paths.front();
    const demos::CompareSpec compare = vary.empty() ? load(path, overrides.scene_arguments).compare : demos::compare_from_vary(vary);
    if (compare.values.empty())
      throw std::invalid_argument(path + ": nothing to compare: give --vary KEY=V1,V2, a [compare] table in the scene, "
                                  "or two to four scene files");
    comparison.scenes = demos::load_variants(path, overrides.scene_arguments.settings, compare);
    labels = compare.labels;
    comparison.paths.assign(compare.values.size(), path);
  } else if (!vary.empty() || scene_paths.size() > 4) {
    throw std::invalid_argument("compare shows two to four panes: give two to four scene files, or one and --vary KEY=V1,V2");
  } else {
    for (const std::string& path : scene_paths) {
      comparison.scenes.push_back(load(path, overrides.scene_arguments));
      labels.push_back(fs::path(path).stem().string());
    }
    comparison.paths = scene_paths;
  }
  for (size_t i = 0; i < comparison.scenes.size(); ++i) {
    demos::Scene& scene = comparison.scenes[i];
    if (i == 0) {
      overrides.apply(scene, options);
    } else {
      const demos::Scene& first = comparison.scenes.front();
      scene.camera = first.camera;
      scene.camera_motion = first.camera_motion;
      scene.video = first.video;
      scene.playback = first.playback;
      scene.duration = first.duration;
    }
    comparison.panes.push_back({&scene, labels[i]});
  }
  return comparison;
}

Comparison load_panes(const std::string& scene_path, const VideoOverrides& overrides, demos::RenderOptions& options) {
  demos::Scene scene = load(scene_path, overrides.scene_arguments);
  if (!scene.compare.values.empty()) return load_comparison({scene_path}, "", overrides, options);
  Comparison alone;
  overrides.apply(scene, options);
  alone.scenes.push_back(std::move(scene));
  alone.paths = {scene_path};
  alone.panes = {{&alone.scenes.front(), ""}};
  return alone;
}

demos::Scene load(const std::string& scene_path, const SceneArguments& arguments, bool typeset) {
  demos::Scene scene = demos::load_scene(scene_path, arguments.settings);
  if (typeset) demos::check_equations(scene);
  for (const std::string& warning : demos::start_warnings(scene)) std::fprintf(stderr, "impulse: %s\n", warning.c_str());
  return scene;
}

int report_checks(const std::string& scene_path, const std::vector<demos::CheckResult>& results) {
  int failed = 0;
  for (const demos::CheckResult& result : results) {
    std::fprintf(stderr, "%s: %s %s: %s\n", scene_path.c_str(), result.passed ? "pass" : "FAIL", result.text.c_str(),
                 result.measured.c_str());
    failed += !result.passed;
  }
  if (failed > 0) std::fprintf(stderr, "impulse: %s: %d of %zu checks failed\n", scene_path.c_str(), failed, results.size());
  return failed > 0 ? kExitCheckFailed : 0;
}

std::string exit_meaning(int exit_code) {
  switch (exit_code) {
    case 0: return "done";
    case kExitBadInput: return "the scene file or the command line is wrong";
    case kExitCheckFailed: return "a [[check]] of the scene failed";
    case kExitOutput: return "the output cannot be written";
    case kExitFailure: return "the renderer or the encoder failed";
  }
  if (exit_code > 128) return "ended by signal " + std::to_string(exit_code - 128);
  return "failed";
}

int report(const std::exception& error) {
  std::fprintf(stderr, "impulse: %s\n", error.what());
  if (dynamic_cast<const render::OutputError*>(&error)) return kExitOutput;
  if (dynamic_cast<const demos::SceneError*>(&error) || dynamic_cast<const std::invalid_argument*>(&error)) {
    return kExitBadInput;
  }
  return kExitFailure;
}

std::string default_video_path(const std::string& scene_path, const std::string& out_directory) {
  return (fs::path(out_directory) / fs::path(scene_path).stem()).string() + ".mp4";
}


int render_one(const std::string& scene_path, demos::RenderOptions options, const VideoOverrides& overrides,
               bool progress) {
  demos::Scene scene = load(scene_path, overrides.scene_arguments);
  if (!scene.compare.values.empty()) return render_comparison({scene_path}, "", options, overrides, progress);
  overrides.apply(scene, options);
  demos::ProgressBar bar(progress, scene_path);
  options.progress = [&bar](int done, int total) { bar.update(done, total); };
  const std::vector<demos::CheckResult> checks = demos::render_scene(scene, options);
  bar.finish();
  if (!options.video_path.empty()) std::fprintf(stderr, "wrote %s\n", options.video_path.c_str());
  if (!options.png_directory.empty()) std::fprintf(stderr, "wrote frames to %s/\n", options.png_directory.c_str());
  return report_checks(scene_path, checks);
}

std::string default_comparison_path(const std::vector<std::string>& scene_paths, const std::string& vary) {
  std::string name = fs::path(scene_paths.front()).stem().string();
  if (!vary.empty()) {
    std::string key = vary.substr(0, vary.find('='));
    std::replace_if(key.begin(), key.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    name += "_" + key;
  } else {
    for (size_t i = 1; i < scene_paths.size(); ++i) name += "_vs_" + fs::path(scene_paths[i]).stem().string();
  }
  return (fs::path("out") / name).string() + ".mp4";
}

int render_comparison(const std::vector<std::string>& scene_paths, const std::string& vary,
                      demos::RenderOptions options, const VideoOverrides& overrides, bool progress) {
  Comparison comparison = load_comparison(scene_paths, vary, overrides, options);
  demos::ProgressBar bar(progress, scene_paths.front());
  options.progress = [&bar](int done, int total) { bar.update(done, total); };
  const std::vector<std::vector<demos::CheckResult>> checks = demos::render_panes(comparison.panes, options);
  bar.finish();
  std::fprintf(stderr, "wrote %s\n", options.video_path.c_str());
  int exit_code = 0;
  for (size_t i = 0; i < checks.size(); ++i)
    exit_code = std::max(exit_code, report_checks(comparison.paths[i] + " [" + comparison.panes[i].label + "]", checks[i]));
  return exit_code;
}

void render_panes_alone(const std::string& scene_path, const std::string& video_path, const VideoOverrides& overrides,
                        bool progress) {
  const demos::CompareSpec compare = demos::load_scene(scene_path, overrides.scene_arguments.settings).compare;
  if (compare.values.empty()) return;
  std::vector<demos::Scene> panes = demos::load_variants(scene_path, overrides.scene_arguments.settings, compare);
  for (size_t i = 0; i < panes.size(); ++i) {
    demos::RenderOptions options;
    options.video_path = demos::pane_video_path(video_path, int(i) + 1);
    overrides.apply(panes[i], options);
    demos::ProgressBar bar(progress, scene_path + " [" + compare.labels[i] + "]");
    options.progress = [&bar](int done, int total) { bar.update(done, total); };
    demos::render_scene(panes[i], options);
    bar.finish();
  }
}

}  // namespace impulse::demos
