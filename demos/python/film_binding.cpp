// Scene.render, impulse.compare and Scene.frames for Python: the film room's render_scene and
// render_panes, as `impulse render` and `impulse compare` call them.
#include "binding.h"

#include "demos/program.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>

namespace impulse::python {
namespace {

// What was written: the video and what sits beside it, and the [[check]]s of each pane.
py::dict written(const demos::RenderOptions& options, const std::vector<std::vector<demos::CheckResult>>& panes) {
  namespace fs = std::filesystem;
  auto if_there = [](const std::string& path) { return fs::exists(path) ? py::object(py::str(path)) : py::object(py::none()); };
  py::dict result;
  result["video"] = options.video_path;
  result["poster"] = if_there(options.poster_path);
  result["captions"] = if_there(demos::captions_path(options.video_path));
  result["chapters"] = if_there(demos::chapters_path(options.video_path));
  py::list checks;
  for (const std::vector<demos::CheckResult>& pane : panes) checks.append(check_list(pane));
  result["checks"] = checks;
  return result;
}

demos::VideoOverrides overrides_for(const std::string& quality) {
  demos::VideoOverrides overrides;
  if (!quality.empty() && !demos::quality_preset(quality))
    throw std::invalid_argument("quality must be \"low\", \"medium\" or \"high\", got \"" + quality + "\"");
  overrides.quality = quality;
  return overrides;
}

demos::RenderOptions video_options(const std::string& path) {
  demos::RenderOptions options;
  options.video_path = path;
  options.poster_path = demos::poster_path(path);
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (!directory.empty()) std::filesystem::create_directories(directory);
  return options;
}

// Renders the panes (one: a scene alone) with the GIL released.
std::vector<std::vector<demos::CheckResult>> render(std::vector<demos::Scene>& scenes, const std::vector<std::string>& labels,
                                                    demos::RenderOptions& options, py::object progress) {
  PythonProgress report(std::move(progress));
  options.progress = [&report](int done, int total) { report(done, total); };
  py::gil_scoped_release released;
  if (scenes.size() == 1) return {demos::render_scene(scenes.front(), options)};
  std::vector<demos::Pane> panes;
  for (size_t i = 0; i < scenes.size(); ++i) panes.push_back({&scenes[i], labels[i]});
  return demos::render_panes(panes, options);
}

}  // namespace

void share_first(std::vector<demos::Scene>& scenes) {
  for (demos::Scene& scene : scenes) {
    scene.camera = scenes.front().camera;
    scene.camera_motion = scenes.front().camera_motion;
    scene.video = scenes.front().video;
    scene.playback = scenes.front().playback;
    scene.duration = scenes.front().duration;
  }
}

std::vector<demos::Scene> scene_panes(const CoreScene& core, std::vector<std::string>& labels) {
  labels = {""};
  if (core.scene.compare.values.empty()) return {core.scene};
  std::vector<demos::Scene> scenes = demos::load_variants(*core.file, core.settings, core.scene.compare);
  if (!core.response.is_none())
    for (demos::Scene& scene : scenes) set_python_response(scene, core.response);
  labels = core.scene.compare.labels;
  share_first(scenes);
  return scenes;
}

void add_film_bindings(py::module_& module) {
  module.def(
      "render",
      [](const CoreScene& core, const std::string& path, const std::string& quality, py::object progress) {
        demos::RenderOptions options = video_options(path);
        std::vector<std::string> labels;
        std::vector<demos::Scene> scenes = scene_panes(core, labels);  // the file's [compare]'s, as `impulse render` shows them
        overrides_for(quality).apply(scenes.front(), options);
        share_first(scenes);
        const auto checks = render(scenes, labels, options, std::move(progress));
        return written(options, checks);
      },
      py::arg("scene"), py::arg("path"), py::arg("quality") = "", py::arg("progress") = py::none());

  module.def(
      "compare",
      [](const std::vector<const CoreScene*>& cores, const std::string& vary, const std::string& path,
         const std::string& quality, py::object progress) {
        demos::RenderOptions options = video_options(path);
        std::vector<demos::Scene> scenes;
        std::vector<std::string> labels;
        if (!vary.empty()) {
          const CoreScene& core = *cores.at(0);
          demos::CompareSpec compare = demos::compare_from_vary(vary);
          compare.origin = "vary " + vary;
          scenes = demos::load_variants(*core.file, core.settings, compare);
          if (!core.response.is_none())
            for (demos::Scene& scene : scenes) set_python_response(scene, core.response);
          labels = compare.labels;
        } else {
          if (cores.size() < 2 || cores.size() > 4)
            throw std::invalid_argument("compare shows two to four panes: give two to four scenes, or one and vary={KEY: [V1, V2]}");
          for (const CoreScene* core : cores) {
            scenes.push_back(core->scene);
            labels.push_back(core->scene.title.empty() ? std::filesystem::path(core->scene.path).stem().string()
                                                       : core->scene.title);
          }
        }
        overrides_for(quality).apply(scenes.front(), options);
        share_first(scenes);
        const auto checks = render(scenes, labels, options, std::move(progress));
        return written(options, checks);
      },
      py::arg("scenes"), py::arg("vary"), py::arg("path"), py::arg("quality") = "", py::arg("progress") = py::none());

  module.def(
      "frames",
      [](const CoreScene& core, std::vector<double> times, const std::string& quality, py::object progress) {
        for (const double t : times)
          if (!(t >= 0 && t <= core.scene.duration))
            throw std::invalid_argument("a frame's time must be within the scene's 0 .. " + std::to_string(core.scene.duration) +
                                        " s, got " + std::to_string(t));
        demos::Scene scene = core.scene;
        demos::RenderOptions options;
        overrides_for(quality).apply(scene, options);
        std::vector<double> moments = times;
        std::sort(moments.begin(), moments.end());
        moments.erase(std::unique(moments.begin(), moments.end()), moments.end());
        options.moments = moments;
        std::map<double, std::vector<uint8_t>> rgb;  // each moment's picture, RGB
        std::mutex guard;
        int width = scene.video.width, height = scene.video.height;
        options.on_still = [&](double time, const render::Frame& frame, const std::vector<demos::BodyPose>&) {
          std::vector<uint8_t> pixels(size_t(frame.width) * frame.height * 3);
          for (size_t i = 0, n = size_t(frame.width) * frame.height; i < n; ++i)
            std::copy_n(&frame.rgba[4 * i], 3, &pixels[3 * i]);
          std::lock_guard lock(guard);
          width = frame.width;
          height = frame.height;
          rgb[time] = std::move(pixels);
        };
        std::vector<demos::Scene> scenes{scene};
        render(scenes, {""}, options, std::move(progress));
        py::array_t<uint8_t> result({py::ssize_t(times.size()), py::ssize_t(height), py::ssize_t(width), py::ssize_t(3)});
        for (size_t i = 0; i < times.size(); ++i) {
          // A still is keyed by the moment it was asked for (the film's stills are the moments given).
          auto found = rgb.lower_bound(times[i] - 1e-12);
          if (found == rgb.end()) throw std::runtime_error("no picture was made at " + std::to_string(times[i]) + " s");
          std::copy(found->second.begin(), found->second.end(), result.mutable_data(py::ssize_t(i)));
        }
        return result;
      },
      py::arg("scene"), py::arg("times"), py::arg("quality") = "", py::arg("progress") = py::none());
}

}  // namespace impulse::python
