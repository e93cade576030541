// `impulse verify`: a course's visual regression check, by moments of simulated time.
//
// `--update` renders a still at each moment (--at, or the start, the middle, the end and each impact
// that slows the video) into DIR/t_0.500.png, and records in DIR/manifest.toml the size, frame rate,
// quality, drawing options, --set arguments and program, and in DIR/poses.csv every body's pose at
// each moment. Without it, the manifest's moments (or --at's) are rendered and compared:
// - each still with its golden by render/image_compare.h (perceptual colour distance, anti-aliased
//   edges forgiven, connected regions of differing pixels);
// - each body's pose with the recorded one, within kPoseMetres and kPoseRadians;
// - a size other than the goldens' differs, with the options that would match them.
// A still that differs gets t_0.500.actual.png, .diff.png and .strip.png (golden | actual | diff)
// beside its golden, and DIR/report.html shows every moment's verdict and images.
#pragma once
#include <string>
#include <vector>

#include "demos/film/render_scene.h"

namespace impulse::demos {

inline constexpr double kPoseMetres = 1e-3;   // a body may be this far from its recorded position
inline constexpr double kPoseRadians = 1e-3;  // and turned this much from its recorded orientation

struct VerifyOptions {
  std::string golden_directory;
  std::string scene_path;             // recorded in the manifest
  std::vector<double> moments;        // --at; empty: the manifest's (or, with update, the default moments)
  std::vector<std::string> settings;  // --set, recorded in the manifest
  bool update = false;                // record the goldens instead of comparing
};

struct VerifyResult {
  std::vector<std::string> lines;  // one per moment (and per body that moved): matches, DIFFERS, wrote
  bool passed = true;
  std::string report_path;          // DIR/report.html; empty with update
  std::vector<std::vector<CheckResult>> checks;  // each pane's [[check]]s, from the same run
};

// `panes`: the scene alone, or a comparison's panes (the poses are the first pane's). Throws
// std::invalid_argument when there is nothing to compare with (no manifest, a moment without
// golden), render::OutputError when a file cannot be written.
VerifyResult verify_scene(const std::vector<Pane>& panes, RenderOptions options, const VerifyOptions& verify);

}  // namespace impulse::demos
