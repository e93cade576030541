// The `impulse` command line: scene files in, teaching videos out.
#include "demos/render_scene.h"
#include "demos/scene_file.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace impulse;

namespace {

std::string default_video_path(const std::string& scene_path, const std::string& out_directory) {
  return (fs::path(out_directory) / fs::path(scene_path).stem()).string() + ".mp4";
}

int render_one(const std::string& scene_path, demos::RenderOptions options) {
  const demos::Scene scene = demos::load_scene(scene_path);
  demos::render_scene(scene, options);
  if (!options.video_path.empty()) std::fprintf(stderr, "wrote %s\n", options.video_path.c_str());
  if (!options.png_directory.empty()) std::fprintf(stderr, "wrote frames to %s/\n", options.png_directory.c_str());
  return 0;
}

int render_catalogue(const std::string& scenes_directory, const std::string& out_directory, bool progress) {
  if (!fs::is_directory(scenes_directory)) {
    std::fprintf(stderr, "impulse: no scene directory '%s' (run from the repository root, or pass --scenes DIR)\n",
                 scenes_directory.c_str());
    return 1;
  }
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(scenes_directory))
    if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  fs::create_directories(out_directory);
  for (const fs::path& scene : scenes) {
    demos::RenderOptions options;
    options.video_path = default_video_path(scene.string(), out_directory);
    options.progress = progress;
    render_one(scene.string(), options);
  }
  std::fprintf(stderr, "rendered %zu scenes into %s/\n", scenes.size(), out_directory.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"impulse: rigid-body collision physics rendered into teaching videos, headless.\n"
               "Scene files are TOML (see README.md, 'Scene files'); videos are H.264 MP4."};
  app.require_subcommand(1);
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "No progress line on stderr");

  auto* render = app.add_subcommand("render", "Simulate one scene file and write it as an MP4 video (and PNG frames)");
  std::string scene_path, video_path, png_directory;
  render->add_option("scene", scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  render->add_option("-o,--output", video_path, "Video to write (default: out/<scene name>.mp4)");
  render->add_option("--png", png_directory, "Also write every frame as PNG into this directory");

  auto* catalogue = app.add_subcommand("catalogue", "Render every scene of a directory into videos");
  std::string scenes_directory = "assets/scenes", out_directory = "out";
  catalogue->add_option("--scenes", scenes_directory, "Directory of scene files")->capture_default_str();
  catalogue->add_option("-o,--output", out_directory, "Directory for the videos")->capture_default_str();

  auto* check = app.add_subcommand("check", "Read a scene file and report any error in it, without rendering");
  check->add_option("scene", scene_path, "Scene file (.toml)")->required();

  CLI11_PARSE(app, argc, argv);
  const bool progress = !quiet && isatty(STDERR_FILENO);
  try {
    if (*render) {
      demos::RenderOptions options;
      options.video_path = video_path.empty() ? default_video_path(scene_path, "out") : video_path;
      options.png_directory = png_directory;
      options.progress = progress;
      if (video_path.empty()) fs::create_directories("out");
      return render_one(scene_path, options);
    }
    if (*catalogue) return render_catalogue(scenes_directory, out_directory, progress);
    if (*check) {
      const demos::Scene scene = demos::load_scene(scene_path);
      std::printf("%s: fine, %zu bodies, %.1f s\n", scene_path.c_str(), scene.bodies.size(), scene.duration);
      return 0;
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impulse: %s\n", error.what());
    return 1;
  }
  return 0;
}
