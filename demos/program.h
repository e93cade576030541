// What the `impulse` commands share: their exit codes, what the command line changes in every
// scene it reads, and rendering a scene or a comparison with a progress bar, its checks reported.
#pragma once
#include "demos/film/render_scene.h"
#include "demos/scene/scene_compare.h"
#include "demos/scene/scene_file.h"
#include "demos/scene/video_quality.h"

#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impulse::demos {

// Exit codes, as README.md lists them. An interrupted run ends by its signal (130, 143 in a shell).
inline constexpr int kExitBadInput = 1;  // the scene file or the command line is wrong; nothing was written
inline constexpr int kExitCheckFailed = 2;  // a [[check]] of the scene did not hold (the outputs are written)
inline constexpr int kExitOutput = 3;    // the output cannot be written; nothing was replaced, no temporary left
inline constexpr int kExitFailure = 4;   // anything else went wrong (the renderer, the encoder)

// What an exit code means, in words: "the output cannot be written", "interrupted by signal 15".
std::string exit_meaning(int exit_code);

// What the command line says about every scene a command reads (command_options.h adds the options).
struct SceneArguments {
  std::vector<std::string> settings;  // --set KEY=VALUE, over the scene file
};

// What the command line changes in every scene a rendering command reads.
struct VideoOverrides {
  SceneArguments scene_arguments;
  std::string quality;  // empty: the scene's
  std::optional<int> width, height, fps, crf;
  std::string x264_preset;  // empty: the scene's
  std::string antialias;        // empty: the renderer's default (edges), or msaa when --samples says
  std::optional<int> samples;  // --samples
  std::string spheres = "impostor";
  std::string shadows = "ground";

  void apply(demos::Scene& scene, demos::RenderOptions& options) const {
    demos::VideoSetting& video = scene.video;
    if (!quality.empty()) {
      const std::string scene_preset = video.preset;  // size, rate and CRF come with the quality, not the encoder speed
      video = *demos::quality_preset(quality);
      video.preset = scene_preset;
    }
    if (width) video.width = *width;
    if (height) video.height = *height;
    if (fps) video.fps = *fps;
    if (crf) video.crf = *crf;
    if (!x264_preset.empty()) video.preset = x264_preset;
    if (video.width % 2 || video.height % 2)
      throw std::invalid_argument("--width and --height must be even (H.264 yuv420p halves the colour planes)");
    if (samples && !antialias.empty() && antialias != "msaa")
      throw std::invalid_argument("--samples is the number of multisamples: use it with --antialias msaa or alone, not with --antialias " + antialias);
    if (antialias == "edges") options.renderer.antialiasing = render::Antialiasing::edges;
    if (antialias == "msaa" || samples) options.renderer.antialiasing = render::Antialiasing::msaa;
    if (antialias == "none" || (samples && *samples == 0)) options.renderer.antialiasing = render::Antialiasing::none;
    if (samples && *samples > 0) options.renderer.samples = *samples;
    options.renderer.spheres = spheres == "tessellated" ? render::SphereMethod::tessellated : render::SphereMethod::impostor;
    options.renderer.shadows = shadows == "map"    ? render::ShadowMethod::shadow_map
                               : shadows == "none" ? render::ShadowMethod::none
                                                   : render::ShadowMethod::ground;
  }
};

// The panes of a comparison: one scene per value of --vary or of the file's [compare], or one per
// scene file; or one scene alone. Every pane gets the first's camera, video, playback and
// duration, and the first scene the command line's video options. A pane points into `scenes`.
// Each scene file is parsed once; the panes of one file are read from that parse.
struct Comparison {
  std::vector<std::string> paths;      // the scene file of each pane
  std::vector<demos::Scene> scenes;
  std::vector<demos::Pane> panes;
  bool alone() const { return scenes.size() == 1; }  // one scene, no comparison
};
Comparison load_comparison(const std::vector<std::string>& scene_paths, const std::string& vary,
                           const VideoOverrides& overrides, demos::RenderOptions& options);
// One scene file as it renders: its [compare]'s panes, or itself alone in one pane.
Comparison load_panes(const std::string& scene_path, const VideoOverrides& overrides, demos::RenderOptions& options);
// The same with the file's own video settings and `arguments` (--set) over it: a page's panes.
Comparison load_panes(const std::string& scene_path, const SceneArguments& arguments);

// The file's scene with the command line's arguments over it; what is odd but allowed is said on
// stderr. With `typeset`, its [[equation]]s' TeX is typeset too (check_equations): a LaTeX error
// is the scene's, with its file and line.
Scene load(const SceneFile& file, const SceneArguments& arguments, bool typeset = true);

// Prints each [[check]]'s result on stderr; the exit code: 0, or kExitCheckFailed if one failed.
int report_checks(const std::string& scene_path, const std::vector<CheckResult>& results);

// Says what went wrong and returns the exit code for it.
int report(const std::exception& error);

std::string default_video_path(const std::string& scene_path, const std::string& out_directory);  // DIR/NAME.mp4
std::string default_comparison_path(const std::vector<std::string>& scene_paths, const std::string& vary);

// A scene alone, or panes side by side, into options.video_path, with a progress bar; its checks
// reported; the exit code.
int render_loaded(const Comparison& loaded, RenderOptions options, bool progress);

// One scene (a comparison if its file has a [compare] table) into options.video_path; the exit code.
int render_one(const std::string& scene_path, RenderOptions options, const VideoOverrides& overrides, bool progress);

// Panes side by side: one per value of `vary` (or of the scene's [compare]), or one per scene file.
int render_comparison(const std::vector<std::string>& scene_paths, const std::string& vary, RenderOptions options,
                      const VideoOverrides& overrides, bool progress);

// Each pane of a comparison alone, beside its video (the gallery links them); their checks were
// reported with the comparison. Nothing for a scene alone.
void render_panes_alone(const Comparison& loaded, const std::string& video_path, const VideoOverrides& overrides,
                        bool progress);

}  // namespace impulse::demos
