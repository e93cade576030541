#include "demos/catalogue.h"

#include "demos/child_jobs.h"
#include "demos/gallery.h"
#include "demos/page/page_export.h"
#include "render/part_file.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;

namespace impulse::demos {
namespace {

bool unchanged(const fs::path& scene, const std::string& video_path) {
  std::error_code video_error, scene_error, program_error;
  const auto video = fs::last_write_time(video_path, video_error);
  const auto scene_time = fs::last_write_time(scene, scene_error);
  const auto program = fs::last_write_time("/proc/self/exe", program_error);
  if (video_error || scene_error || program_error) return false;
  return video > scene_time && video > program;
}

using Failures = std::map<std::string, int>;  // scene file name -> its exit code, for the gallery

// --jobs N: each scene in a child process, the longest first; the worst exit code.
int render_in_jobs(const std::vector<fs::path>& scenes, std::vector<size_t> chosen, const VideoOverrides& overrides,
                   const CatalogueChoice& choice, Failures& failed) {
  // The longest first, so that the last to end does not start last: an estimate of each scene's
  // work from its length, bodies and panes (its own and rendered alone).
  std::vector<double> work(scenes.size(), 0.0);
  for (size_t i : chosen) try {
      const demos::Scene scene = demos::load_scene(scenes[i].string(), overrides.scene_arguments.settings);
      work[i] = scene.duration * (1 + scene.bodies.size() / 100.0) * std::max<size_t>(1, 2 * scene.compare.values.size());
    } catch (const std::exception&) {
      // its job reports what is wrong with it
    }
  std::stable_sort(chosen.begin(), chosen.end(), [&](size_t a, size_t b) { return work[a] > work[b]; });
  std::vector<std::vector<std::string>> jobs;
  for (size_t i : chosen) {
    jobs.push_back(choice.child_arguments);
    jobs.back().insert(jobs.back().end(), {"--only", scenes[i].filename().string()});
  }
  std::vector<std::chrono::steady_clock::time_point> starts(jobs.size());
  auto line = [&](size_t job) {
    char number[48];
    std::snprintf(number, sizeof number, "[%zu/%zu] ", chosen[job] + 1, scenes.size());
    return number + scenes[chosen[job]].string();
  };
  return demos::run_child_jobs(
      jobs, choice.jobs,
      [&](size_t job) {
        starts[job] = std::chrono::steady_clock::now();
        std::fprintf(stderr, "%s: started\n", line(job).c_str());
      },
      [&, finished = size_t(0), began = std::chrono::steady_clock::now()](size_t job, int code) mutable {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - starts[job]).count();
        const std::string outcome = code == 0 ? "done" : "failed (exit " + std::to_string(code) + ")";
        if (code != 0) failed[scenes[chosen[job]].filename().string()] = code;
        std::fprintf(stderr, "%s: %s in %.1f s; %zu of %zu scenes finished, %.0f s so far\n", line(job).c_str(), outcome.c_str(),
                     seconds, ++finished, jobs.size(), std::chrono::duration<double>(now - began).count());
      });
}

// One scene after the other in this process. A scene that fails is reported and the next one
// rendered: one takes no other with it. The worst exit code.
int render_in_turn(const std::vector<fs::path>& scenes, const std::vector<size_t>& chosen, const std::string& out_directory,
                   bool progress, const VideoOverrides& overrides, const CatalogueChoice& choice, Failures& failed) {
  int exit_code = 0;
  for (size_t i : chosen) {
    const fs::path& scene = scenes[i];
    demos::RenderOptions options;
    options.video_path = default_video_path(scene.string(), out_directory);
    options.poster_path = demos::poster_path(options.video_path);
    if (choice.only.empty()) std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, scenes.size(), scene.c_str());
    int code = 0;
    try {
      const Comparison loaded = load_panes(scene.string(), overrides, options);  // the file parsed once
      code = render_loaded(loaded, options, progress);
      render_panes_alone(loaded, options.video_path, overrides, progress);
      // Its interactive page beside it, `impulse export`'s (the file's own video settings), which
      // the gallery links.
      static const std::string script = demos::page_script();
      const Comparison own = load_panes(scene.string(), overrides.scene_arguments);
      render::write_file(demos::page_path(options.video_path), [&](std::ostream& out) { demos::write_page(own.panes, script, out); });
    } catch (const std::exception& error) {
      code = report(error);
    }
    if (code != 0) failed[scene.filename().string()] = code;
    exit_code = std::max(exit_code, code);
  }
  return exit_code;
}

}  // namespace

std::vector<std::string> job_arguments(const std::vector<std::string>& arguments) {
  std::vector<std::string> kept{"--quiet"};
  for (size_t i = 0; i < arguments.size(); ++i) {
    const std::string& word = arguments[i];
    if (word == "--jobs" || word == "--shard") {
      ++i;
      continue;
    }
    if (word.starts_with("--jobs=") || word.starts_with("--shard=") || word == "--changed-only" || word == "--progress" ||
        word == "-q" || word == "--quiet")
      continue;
    kept.push_back(word);
  }
  return kept;
}

int render_catalogue(const std::string& scenes_directory, const std::string& out_directory, bool progress,
                     const VideoOverrides& overrides, const CatalogueChoice& choice) {
  if (!fs::is_directory(scenes_directory)) {
    std::fprintf(stderr, "impulse: no scene directory '%s' (run from the repository root, or pass --scenes DIR)\n",
                 scenes_directory.c_str());
    return kExitBadInput;
  }
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(scenes_directory))
    if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  fs::create_directories(out_directory);
  std::vector<size_t> chosen;
  for (size_t i = 0; i < scenes.size(); ++i) {
    if (int(i % size_t(choice.shards)) != choice.shard - 1) continue;
    if (!choice.only.empty() && scenes[i].filename() != choice.only) continue;
    const std::string video_path = default_video_path(scenes[i].string(), out_directory);
    if (choice.changed_only && unchanged(scenes[i], video_path)) {
      std::fprintf(stderr, "[%zu/%zu] %s: unchanged, kept %s\n", i + 1, scenes.size(), scenes[i].c_str(), video_path.c_str());
      continue;
    }
    chosen.push_back(i);
  }
  Failures failed;
  const int exit_code = choice.jobs > 1 && chosen.size() > 1
                            ? render_in_jobs(scenes, chosen, overrides, choice, failed)
                            : render_in_turn(scenes, chosen, out_directory, progress, overrides, choice, failed);
  if (!choice.only.empty()) return exit_code;  // one job of --jobs: its parent writes the gallery
  const auto unrendered = std::count_if(failed.begin(), failed.end(), [](const auto& f) { return f.second != kExitCheckFailed; });
  std::fprintf(stderr, "rendered %zu of %zu scenes into %s/", chosen.size() - size_t(unrendered), scenes.size(),
               out_directory.c_str());
  if (unrendered > 0) std::fprintf(stderr, "; %zu failed", size_t(unrendered));
  std::fprintf(stderr, "\n");
  const int videos = demos::write_gallery(scenes_directory, out_directory, failed);
  std::fprintf(stderr, "wrote %s/index.html (%d videos%s)\n", out_directory.c_str(), videos,
               failed.empty() ? "" : ", the failed scenes marked");
  return exit_code;
}

}  // namespace impulse::demos
