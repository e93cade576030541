// `impulse verify`: stills at chosen moments and every body's pose, compared with goldens (verify.h).
#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/film/moments.h"
#include "demos/golden_manifest.h"
#include "demos/verify.h"
#include "render/image_compare.h"

#include <algorithm>
#include <cstdio>
#include <memory>

namespace impulse::demos {
namespace {

struct VerifyArguments {
  std::string scene_path;
  std::string moments;
  VerifyOptions verify;
  VideoOverrides overrides;
};

// verify's --help footer, with the tolerances it uses.
std::string verify_help() {
  const render::ImageTolerance tolerance;
  char text[3000];
  std::snprintf(
      text, sizeof text,
      "\nMoments are seconds of simulated time, so goldens survive a change of frame rate. By default --update\n"
      "records the start, the middle, the end and each impact that slows the video; a later run compares the\n"
      "moments the goldens' manifest.toml lists (size, frame rate, quality, drawing options, --set, program),\n"
      "at the size and frame rate it records unless --quality, --width, --height or --fps say otherwise.\n"
      "\nA pixel differs when its perceptual (YIQ) colour distance is over %.2f and it is not an anti-aliased\n"
      "edge; a still differs when a connected region of more than %d such pixels, or more than %.2f %% of\n"
      "the frame, differs, or a region of more than %d pixels over a fainter %.2f (a pale, sleeping body\n"
      "recoloured). A body differs when it is more than %g m from its recorded position or turned\n"
      "more than %g rad (poses.csv). A still that differs gets t_0.500.actual.png, .diff.png and .strip.png\n"
      "(golden | actual | diff) beside its golden; DIR/report.html shows every moment.\n"
      "\nExamples:\n"
      "  impulse verify course/drop.toml --golden course/golden/drop --quality low --update   # record\n"
      "  impulse verify course/drop.toml --golden course/golden/drop                          # compare\n"
      "  impulse verify scene.toml --golden golden/ --at 0.5,1,2 --update                    # chosen moments\n"
      "\nExit codes: 0 every still and pose matches (or the goldens were written); 1 the scene file or the\n"
      "command line is wrong, or there is nothing to compare with (no manifest, a moment without golden);\n"
      "2 a still or a body's pose differs, or the size is not the goldens' (it says what to re-run), or a\n"
      "[[check]] of the scene failed; 3 a file cannot be written; 4 anything else failed.",
      tolerance.colour_threshold, tolerance.max_region_pixels, 100 * tolerance.max_differing_share,
      tolerance.max_faint_region_pixels, tolerance.faint_threshold, kPoseMetres, kPoseRadians);
  return text;
}

// A comparison renders at the goldens' size and frame rate (their manifest's) unless the command
// line says otherwise: --quality (its size and rate), --width, --height, --fps or --set video.*.
void size_of_goldens(const std::string& golden_directory, VideoOverrides& overrides) {
  if (!overrides.quality.empty()) return;
  for (const std::string& setting : overrides.scene_arguments.settings)
    if (setting.rfind("video.", 0) == 0 || setting.rfind("video[", 0) == 0) return;
  const GoldenManifest manifest = read_manifest(golden_directory);
  if (!overrides.width) overrides.width = manifest.width;
  if (!overrides.height) overrides.height = manifest.height;
  if (!overrides.fps && manifest.fps > 0) overrides.fps = manifest.fps;
}

int verify(VerifyArguments arguments) {
  const std::string& path = arguments.scene_path;
  if (!arguments.verify.update) size_of_goldens(arguments.verify.golden_directory, arguments.overrides);
  RenderOptions options;
  const Comparison panes = load_panes(path, arguments.overrides, options);
  VerifyOptions& verify = arguments.verify;
  if (!arguments.moments.empty()) verify.moments = parse_moments(arguments.moments, "--at");
  verify.scene_path = path;
  verify.settings = arguments.overrides.scene_arguments.settings;
  const VerifyResult result = verify_scene(panes.panes, options, verify);
  for (const std::string& line : result.lines) std::fprintf(stderr, "%s: %s\n", path.c_str(), line.c_str());
  int checks = 0;
  for (size_t i = 0; i < result.checks.size(); ++i) {
    const std::string& label = panes.panes[i].label;
    checks = std::max(checks, report_checks(label.empty() ? path : path + " [" + label + "]", result.checks[i]));
  }
  return result.passed ? checks : kExitCheckFailed;
}

}  // namespace

void add_verify_command(Commands& commands) {
  auto arguments = std::make_shared<VerifyArguments>();
  CLI::App* command = commands.add(
      "verify", "Render stills at chosen moments and compare them, and every body's pose, with goldens", verify_help(),
      [arguments](const Invocation&) { return verify(*arguments); });
  command->add_option("scene", arguments->scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  command->add_option("--golden", arguments->verify.golden_directory,
                      "Directory of the goldens: t_0.500.png ..., manifest.toml, poses.csv")
      ->required();
  command->add_option("--at", arguments->moments,
                      "Moments to compare, in seconds of simulated time, e.g. 0.5,1,2 (default: the goldens' manifest's; "
                      "with --update: start, middle, end and each impact that slows the video)");
  command->add_flag("--update", arguments->verify.update,
                    "Record the stills, manifest and poses as the goldens instead of comparing");
  add_video_options(command, arguments->overrides);
}

}  // namespace impulse::demos
