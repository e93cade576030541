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

namespace {

// The panes of `compare`, read from the one parse of `file`.
Comparison panes_of(const SceneFile& file, const CompareSpec& compare, const VideoOverrides& overrides) {
  Comparison comparison;
  comparison.scenes = demos::load_variants(file, overrides.scene_arguments.settings, compare);
  for (const std::string& warning : demos::compare_warnings(comparison.scenes, compare)) std::fprintf(stderr, "impulse: %s\n", warning.c_str());
  comparison.paths.assign(compare.values.size(), file.path());
  for (size_t i = 0; i < comparison.scenes.size(); ++i) comparison.panes.push_back({nullptr, compare.labels[i]});
  return comparison;
}

// Every pane the first's camera, video, playback and duration; the first the command line's
// video options.
void share_first(Comparison& comparison, const VideoOverrides& overrides, demos::RenderOptions& options) {
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
    comparison.panes[i].scene = &scene;
  }
}

}  // namespace

Comparison load_comparison(const std::vector<std::string>& scene_paths, const std::string& vary,
                           const VideoOverrides& overrides, demos::RenderOptions& options) {
  Comparison comparison;
  if (scene_paths.size() == 1) {
    const SceneFile file(scene_paths.front());
    const demos::CompareSpec compare =
        vary.empty() ? load(file, overrides.scene_arguments).compare : demos::compare_from_vary(vary);
    if (compare.values.empty())
      throw std::invalid_argument(file.path() + ": nothing to compare: give --vary KEY=V1,V2, a [compare] table in the "
                                  "scene, or two to four scene files");
    comparison = panes_of(file, compare, overrides);
  } else if (!vary.empty() || scene_paths.size() > 4) {
    throw std::invalid_argument("compare shows two to four panes: give two to four scene files, or one and --vary KEY=V1,V2");
  } else {
    for (const std::string& path : scene_paths) {
      comparison.scenes.push_back(load(SceneFile(path), overrides.scene_arguments));
      comparison.panes.push_back({nullptr, fs::path(path).stem().string()});
    }
    comparison.paths = scene_paths;
  }
  share_first(comparison, overrides, options);
  return comparison;
}

Comparison load_panes(const std::string& scene_path, const VideoOverrides& overrides, demos::RenderOptions& options) {
  const SceneFile file(scene_path);
  demos::Scene scene = load(file, overrides.scene_arguments);
  Comparison loaded;
  if (!scene.compare.values.empty()) {
    loaded = panes_of(file, scene.compare, overrides);
  } else {
    loaded.scenes.push_back(std::move(scene));
    loaded.paths = {scene_path};
    loaded.panes = {{nullptr, ""}};
  }
  share_first(loaded, overrides, options);
  return loaded;
}

Comparison load_panes(const std::string& scene_path, const SceneArguments& arguments) {
  VideoOverrides overrides;
  overrides.scene_arguments = arguments;
  demos::RenderOptions options;
  return load_panes(scene_path, overrides, options);
}

demos::Scene load(const SceneFile& file, const SceneArguments& arguments, bool typeset) {
  demos::Scene scene = file.scene(arguments.settings);
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

int render_loaded(const Comparison& loaded, demos::RenderOptions options, bool progress) {
  demos::ProgressBar bar(progress, loaded.paths.front());
  options.progress = [&bar](int done, int total) { bar.update(done, total); };
  if (loaded.alone()) {
    const std::vector<demos::CheckResult> checks = demos::render_scene(loaded.scenes.front(), options);
    bar.finish();
    if (!options.video_path.empty()) std::fprintf(stderr, "wrote %s\n", options.video_path.c_str());
    if (!options.png_directory.empty()) std::fprintf(stderr, "wrote frames to %s/\n", options.png_directory.c_str());
    return report_checks(loaded.paths.front(), checks);
  }
  std::vector<std::string> warnings;
  options.on_warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
  const std::vector<std::vector<demos::CheckResult>> checks = demos::render_panes(loaded.panes, options);
  bar.finish();
  std::fprintf(stderr, "wrote %s\n", options.video_path.c_str());
  for (const std::string& warning : warnings) std::fprintf(stderr, "impulse: warning: %s\n", warning.c_str());
  int exit_code = 0;
  for (size_t i = 0; i < checks.size(); ++i)
    exit_code = std::max(exit_code, report_checks(loaded.paths[i] + " [" + loaded.panes[i].label + "]", checks[i]));
  return exit_code;
}

int render_one(const std::string& scene_path, demos::RenderOptions options, const VideoOverrides& overrides,
               bool progress) {
  const Comparison loaded = load_panes(scene_path, overrides, options);
  return render_loaded(loaded, options, progress);
}

int render_comparison(const std::vector<std::string>& scene_paths, const std::string& vary,
                      demos::RenderOptions options, const VideoOverrides& overrides, bool progress) {
  const Comparison loaded = load_comparison(scene_paths, vary, overrides, options);
  return render_loaded(loaded, options, progress);
}

void render_panes_alone(const Comparison& loaded, const std::string& video_path, const VideoOverrides& overrides,
                        bool progress) {
  if (loaded.alone()) return;
  for (size_t i = 0; i < loaded.scenes.size(); ++i) {
    demos::Scene pane = loaded.scenes[i];
    demos::RenderOptions options;
    options.video_path = demos::pane_video_path(video_path, int(i) + 1);
    overrides.apply(pane, options);
    demos::ProgressBar bar(progress, loaded.paths[i] + " [" + loaded.panes[i].label + "]");
    options.progress = [&bar](int done, int total) { bar.update(done, total); };
    demos::render_scene(pane, options);
    bar.finish();
  }
}

}  // namespace impulse::demos
