// The `impulse` command line: scene files in, teaching videos out.
#include "demos/catalogue.h"
#include "demos/film/moments.h"
#include "demos/gallery.h"
#include "demos/interrupts.h"
#include "demos/program.h"
#include "demos/simulate.h"
#include "demos/verify.h"
#include "demos/workshop/workshop_commands.h"
#include "render/image_compare.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace impulse;
using namespace impulse::demos;

namespace {

std::vector<int> parse_frames(const std::string& list) {
  std::vector<int> frames;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    try {
      size_t used = 0;
      const int frame = std::stoi(item, &used);
      if (used != item.size() || frame < 0) throw std::invalid_argument(item);
      frames.push_back(frame);
    } catch (const std::exception&) {
      throw std::invalid_argument("--frames wants frame numbers from 0, separated by commas (like 0,45,90), got '" + list + "'");
    }
  }
  return frames;
}

// The video (the default one in out/, made if need be) and the PNG frames and stills asked for.
demos::RenderOptions output_options(const std::string& video_path, const std::string& default_path,
                                    const std::string& png_directory, const std::string& frame_list,
                                    const std::string& moment_list) {
  demos::RenderOptions options;
  options.video_path = video_path.empty() ? default_path : video_path;
  options.png_directory = png_directory;
  if (!frame_list.empty()) {
    if (png_directory.empty()) throw std::invalid_argument("--frames chooses PNG frames: add --png DIR");
    options.png_frames = parse_frames(frame_list);
  }
  if (!moment_list.empty()) {
    if (png_directory.empty()) throw std::invalid_argument("--at chooses PNG stills: add --png DIR");
    options.moments = demos::parse_moments(moment_list, "--at");
  }
  if (video_path.empty()) fs::create_directories(fs::path(default_path).parent_path());
  return options;
}

void add_set_option(CLI::App* command, std::vector<std::string>& settings) {
  command->add_option("--set", settings,
                      "KEY=VALUE: a scene field over the file's, checked as the file's are; repeatable. "
                      "world.friction=false, world.method=projection, body[ball].restitution=0.2, body[0].mass=2, "
                      "video.quality=low, caption[1].text=Hello (a bare word is a string)")
      ->type_name("KEY=VALUE");
}

void add_video_options(CLI::App* command, VideoOverrides& overrides) {
  add_set_option(command, overrides.settings);
  command->add_option("--quality", overrides.quality,
                      "Preset: low (854x480, 15 fps), medium (1280x720, 30 fps), high (1920x1080, 60 fps); "
                      "default: the scene's [video], else medium")
      ->check(CLI::IsMember({"low", "medium", "high"}));
  command->add_option("--width", overrides.width, "Frame width in pixels (even), over the preset")->check(CLI::Range(16, 7680));
  command->add_option("--height", overrides.height, "Frame height in pixels (even)")->check(CLI::Range(16, 4320));
  command->add_option("--fps", overrides.fps, "Frames per second of video (the physics keeps its own step)")
      ->check(CLI::Range(1, 240));
  command->add_option("--crf", overrides.crf, "H.264 constant rate factor: 0 lossless .. 51 worst; 18-23 look clean")
      ->check(CLI::Range(0, 51));
  command->add_option("--x264-preset", overrides.x264_preset,
                      "Encoder speed against file size: superfast (default), veryfast (about half the size, "
                      "slower), ... medium")
      ->check(CLI::IsMember({"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"}));
  command->add_option("--samples", overrides.samples, "Multisample anti-aliasing: 4 (default) or 0 for none")
      ->check(CLI::IsMember({0, 2, 4, 8}));
  command->add_option("--spheres", overrides.spheres,
                      "How spheres are drawn: impostor (ray-cast, default) or tessellated (size-chosen meshes)")
      ->check(CLI::IsMember({"impostor", "tessellated"}));
  command->add_option("--shadows", overrides.shadows,
                      "Shadows: ground (on the ground only, drawn as geometry; default), map (on every body too, "
                      "from a shadow map; slower) or none")
      ->check(CLI::IsMember({"ground", "map", "none"}));
}

}  // namespace

// verify's --help footer, with the tolerances it uses.
std::string verify_help() {
  const render::ImageTolerance tolerance;
  char text[2400];
  std::snprintf(
      text, sizeof text,
      "\nMoments are seconds of simulated time, so goldens survive a change of frame rate. By default --update\n"
      "records the start, the middle, the end and each impact that slows the video; a later run compares the\n"
      "moments the goldens' manifest.toml lists (size, frame rate, quality, drawing options, --set, program).\n"
      "\nA pixel differs when its perceptual (YIQ) colour distance is over %.2f and it is not an anti-aliased\n"
      "edge; a still differs when a connected region of more than %d such pixels, or more than %.2f %% of\n"
      "the frame, differs. A body differs when it is more than %g m from its recorded position or turned\n"
      "more than %g rad (poses.csv). A still that differs gets t_0.500.actual.png, .diff.png and .strip.png\n"
      "(golden | actual | diff) beside its golden; DIR/report.html shows every moment.\n"
      "\nExamples:\n"
      "  impulse verify course/drop.toml --golden course/golden/drop --quality low --update   # record\n"
      "  impulse verify course/drop.toml --golden course/golden/drop --quality low            # compare\n"
      "  impulse verify scene.toml --golden golden/ --at 0.5,1,2 --update                    # chosen moments\n"
      "\nExit codes: 0 every still and pose matches (or the goldens were written); 1 the scene file or the\n"
      "command line is wrong, or there is nothing to compare with (no manifest, a moment without golden);\n"
      "2 a still or a body's pose differs, or the size is not the goldens' (it says what to re-run), or a\n"
      "[[check]] of the scene failed; 3 a file cannot be written; 4 anything else failed.",
      tolerance.colour_threshold, tolerance.max_region_pixels, 100 * tolerance.max_differing_share, demos::kPoseMetres,
      demos::kPoseRadians);
  return text;
}

constexpr const char* kExitCodes =
    "\nExit codes: 0 done; 1 the scene file or the command line is wrong (nothing written); 2 a [[check]]\n"
    "of the scene or a golden frame (verify) failed (outputs written); 3 the output cannot be written (nothing replaced, no temporary\n"
    "left); 4 anything else failed; 130 / 143 interrupted by SIGINT / SIGTERM.";

int main(int argc, char** argv) {
  CLI::App app{"impulse: rigid-body collision physics rendered into teaching videos, headless.\n"
               "Scene files are TOML (see README.md, 'Scene files'); videos are H.264 MP4 (BT.709, faststart),\n"
               "written to a temporary of their own (NAME.mp4.PID-N.part) and renamed when complete:\n"
               "renders into one path at once each leave a complete video, the last to finish wins."};
  app.footer(std::string("\nExamples:\n"
                         "  impulse render assets/scenes/bounce.toml                  # -> out/bounce.mp4\n"
                         "  impulse render assets/scenes/bounce.toml --set world.friction=false -o no_friction.mp4\n"
                         "  impulse compare assets/scenes/bounce.toml --vary world.method=impulse,penalty\n"
                         "  impulse simulate assets/scenes/bounce.toml --trace bodies.csv --world world.csv\n"
                         "  impulse catalogue -o out                                  # every scene of assets/scenes\n") +
             kExitCodes);
  app.require_subcommand(1);
  app.fallthrough();  // -q and --progress also after the subcommand
  bool quiet = false, force_progress = false;
  app.add_flag("-q,--quiet", quiet, "No progress bar on stderr");
  app.add_flag("--progress", force_progress, "A progress bar even when stderr is not a terminal (e.g. in a log)");

  auto* render = app.add_subcommand("render", "Simulate one scene file and write it as an MP4 video (and PNG frames)");
  render->footer(std::string("\nExamples:\n"
                             "  impulse render assets/scenes/bounce.toml -o out/bounce.mp4\n"
                             "  impulse render assets/scenes/bounce.toml --quality low --set body[0].restitution=0.9\n"
                             "  impulse render assets/scenes/s4_angular.toml --png frames --frames 0,45,90\n"
                             "  impulse render assets/scenes/s4_angular.toml --png stills --at 0.5,1,2   # stills/t_0.500.png ...\n") +
                 kExitCodes);
  std::string scene_path, video_path, png_directory, frame_list, moment_list;
  VideoOverrides render_overrides;
  render->add_option("scene", scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  render->add_option("-o,--output", video_path, "Video to write (default: out/<scene name>.mp4)");
  render->add_option("--png", png_directory, "Also write frames as PNG (frame_00000.png, ...) into this directory");
  render->add_option("--frames", frame_list, "With --png: only these frames, numbered from 0, e.g. 0,45,90");
  render->add_option("--at", moment_list,
                     "With --png: stills at these moments of simulated time, in seconds (t_0.500.png, ...), "
                     "e.g. 0.5,1,2; the video's frames are then not written as PNG unless --frames says so");
  add_video_options(render, render_overrides);
  workshop::add_response_options(render, render_overrides.settings);

  auto* compare = app.add_subcommand("compare", "Two to four settings or scenes side by side in one video, one pane each");
  compare->footer(std::string("\nThe panes share the first scene's camera, video, playback and duration, and the same simulated\n"
                              "time; each is labelled with what sets it apart; plots draw every pane's curve in its colour.\n"
                              "\nExamples:\n"
                              "  impulse compare assets/scenes/bounce.toml --vary world.method=impulse,penalty\n"
                              "  impulse compare assets/scenes/s4_angular.toml --vary world.friction=true,false\n"
                              "  impulse compare a.toml b.toml -o a_vs_b.mp4\n") +
                  kExitCodes);
  std::vector<std::string> compare_paths;
  std::string vary, compare_video_path, compare_png_directory, compare_frame_list, compare_moment_list;
  VideoOverrides compare_overrides;
  compare->add_option("scenes", compare_paths, "Scene files (.toml): one with --vary, else two to four")
      ->required()
      ->check(CLI::ExistingFile);
  compare->add_option("--vary", vary, "KEY=V1,V2[,V3[,V4]]: one pane per value of a scene field (as --set writes it)")
      ->type_name("KEY=VALUES");
  compare->add_option("-o,--output", compare_video_path,
                      "Video to write (default: out/<scene>_<key>.mp4, or out/<a>_vs_<b>.mp4)");
  compare->add_option("--png", compare_png_directory, "Also write frames as PNG (frame_00000.png, ...) into this directory");
  compare->add_option("--frames", compare_frame_list, "With --png: only these frames, numbered from 0, e.g. 0,45,90");
  compare->add_option("--at", compare_moment_list, "With --png: stills at these moments in seconds (t_0.500.png, ...)");
  add_video_options(compare, compare_overrides);
  workshop::add_response_options(compare, compare_overrides.settings);

  auto* catalogue = app.add_subcommand("catalogue", "Render every scene of a directory into videos");
  catalogue->footer(std::string("\nExamples:\n"
                                "  impulse catalogue -o out\n"
                                "  impulse catalogue --scenes my_course/ -o videos/ --quality low\n"
                                "  impulse catalogue --shard 2/4 -o out     # the second of four CI jobs\n"
                                "  impulse catalogue --changed-only -o out  # only scenes edited since their video\n"
                                "  impulse catalogue --jobs 2 -o out        # two scenes at once\n") +
                    kExitCodes);
  std::string scenes_directory = "assets/scenes", out_directory = "out";
  VideoOverrides catalogue_overrides;
  catalogue->add_option("--scenes", scenes_directory, "Directory of scene files")->capture_default_str();
  catalogue->add_option("-o,--output", out_directory, "Directory for the videos")->capture_default_str();
  CatalogueChoice catalogue_choice;
  std::string shard;
  catalogue->add_option("--shard", shard, "K/N: render only every Nth scene in name order, from the Kth (CI jobs in parallel)")
      ->type_name("K/N");
  catalogue->add_option("--jobs", catalogue_choice.jobs, "Scenes rendered at once, each in a process of its own (default 1)")
      ->check(CLI::Range(1, 16));
  catalogue->add_option("--only", catalogue_choice.only, "")->group("");  // one job of --jobs
  catalogue->add_flag("--changed-only", catalogue_choice.changed_only,
                      "Skip a scene whose video is newer than its scene file and the program (not after --set or --quality changes)");
  add_video_options(catalogue, catalogue_overrides);

  auto* gallery = app.add_subcommand("gallery", "Write OUT/index.html: every video of the catalogue, for students");
  gallery->footer(std::string("\nThe catalogue writes it too, after its videos. It works opened from disk and served by any\n"
                              "static server.\n\nExamples:\n"
                              "  impulse gallery -o out && xdg-open out/index.html\n"
                              "  impulse gallery --scenes my_course/ -o videos/ && python3 -m http.server -d videos\n") +
                  kExitCodes);
  std::string gallery_scenes = "assets/scenes", gallery_out = "out";
  gallery->add_option("--scenes", gallery_scenes, "Directory of the scene files the videos were made from")->capture_default_str();
  gallery->add_option("-o,--output", gallery_out, "Directory of the videos; index.html goes there")->capture_default_str();

  auto* simulate = app.add_subcommand("simulate", "Simulate a scene and write its numbers as CSV, without pictures");
  simulate->footer(std::string("\nExamples:\n"
                               "  impulse simulate assets/scenes/bounce.toml --trace bodies.csv\n"
                               "  impulse simulate scene.toml --duration 2 --every 6 --contacts contacts.csv --world world.csv\n"
                               "  impulse simulate scene.toml --set world.friction=false --trace no_friction.csv\n") +
                   kExitCodes);
  demos::TraceOptions trace;
  std::vector<std::string> simulate_settings;
  simulate->add_option("scene", scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  simulate->add_option("--duration", trace.duration, "Seconds of simulated time (default: the scene's)")
      ->check(CLI::Range(0.0, 36000.0));
  simulate->add_option("--every", trace.every, "Write every Nth step (and the last); default 1")->check(CLI::Range(1, 1000000));
  simulate->add_option("--trace", trace.bodies_path, "CSV: a row per body per step (time, position, orientation, velocities)");
  simulate->add_option("--contacts", trace.contacts_path,
                       "CSV: a row per contact per step (bodies, point, normal, penetration, impulses)");
  simulate->add_option("--world", trace.world_path, "CSV: a row per step (energies, linear and angular momentum)");
  add_set_option(simulate, simulate_settings);
  workshop::add_response_options(simulate, simulate_settings);

  auto* verify = app.add_subcommand("verify", "Render stills at chosen moments and compare them, and every body's pose, with goldens");
  verify->footer(verify_help());
  demos::VerifyOptions verify_options;
  std::string verify_moments;
  VideoOverrides verify_overrides;
  verify->add_option("scene", scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  verify->add_option("--golden", verify_options.golden_directory,
                     "Directory of the goldens: t_0.500.png ..., manifest.toml, poses.csv")
      ->required();
  verify->add_option("--at", verify_moments,
                     "Moments to compare, in seconds of simulated time, e.g. 0.5,1,2 (default: the goldens' manifest's; "
                     "with --update: start, middle, end and each impact that slows the video)");
  verify->add_flag("--update", verify_options.update, "Record the stills, manifest and poses as the goldens instead of comparing");
  add_video_options(verify, verify_overrides);

  auto* check = app.add_subcommand("check", "Read a scene file and report any error in it, without rendering");
  check->footer(std::string("\nExamples:\n"
                            "  impulse check assets/scenes/bounce.toml\n"
                            "  impulse check scene.toml --set body[ball].restitution=1.2   # refused: e in [0, 1]\n"
                            "  impulse check --simulate assets/scenes/bounce.toml          # its [[check]]s, measured\n") +
                kExitCodes);
  std::vector<std::string> check_settings;
  bool check_simulate = false;
  check->add_option("scene", scene_path, "Scene file (.toml)")->required();
  check->add_flag("--simulate", check_simulate, "Also simulate the scene and report each of its [[check]]s");
  add_set_option(check, check_settings);

  workshop::WorkshopCommands workshop_commands(app);  // response, grade

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kExitBadInput;  // --help is no error
  }
  demos::install_interrupt_handlers();
  const bool progress = !quiet && (force_progress || isatty(STDERR_FILENO));
  try {
    if (workshop_commands.chosen()) return workshop_commands.run(progress);
    if (*render) {
      demos::RenderOptions options = output_options(video_path, default_video_path(scene_path, "out"), png_directory, frame_list,
                                                           moment_list);
      return render_one(scene_path, options, render_overrides, progress);
    }
    if (*compare) {
      demos::RenderOptions options = output_options(compare_video_path, default_comparison_path(compare_paths, vary),
                                                    compare_png_directory, compare_frame_list, compare_moment_list);
      return render_comparison(compare_paths, vary, options, compare_overrides, progress);
    }
    if (*gallery) {
      if (!fs::is_directory(gallery_out)) throw std::invalid_argument("no video directory '" + gallery_out + "' (render the catalogue first)");
      const int videos = demos::write_gallery(gallery_scenes, gallery_out);
      std::fprintf(stderr, "wrote %s/index.html (%d videos)\n", gallery_out.c_str(), videos);
      return 0;
    }
    if (*catalogue) {
      if (!shard.empty()) {
        const size_t slash = shard.find('/');
        try {
          catalogue_choice.shard = std::stoi(shard.substr(0, slash));
          catalogue_choice.shards = std::stoi(shard.substr(slash + 1));
        } catch (const std::exception&) {
          catalogue_choice.shards = 0;
        }
        if (slash == std::string::npos || catalogue_choice.shards < 1 || catalogue_choice.shards > 1000 ||
            catalogue_choice.shard < 1 || catalogue_choice.shard > catalogue_choice.shards)
          throw std::invalid_argument("--shard wants K/N with 1 <= K <= N (like 2/4), got '" + shard + "'");
      }
      catalogue_choice.child_arguments = job_arguments(argc, argv);
      return render_catalogue(scenes_directory, out_directory, progress, catalogue_overrides, catalogue_choice);
    }
    if (*verify) {
      demos::RenderOptions options;
      const Comparison panes = load_panes(scene_path, verify_overrides, options);
      if (!verify_moments.empty()) verify_options.moments = demos::parse_moments(verify_moments, "--at");
      verify_options.scene_path = scene_path;
      verify_options.settings = verify_overrides.settings;
      const demos::VerifyResult result = demos::verify_scene(panes.panes, options, verify_options);
      for (const std::string& line : result.lines) std::fprintf(stderr, "%s: %s\n", scene_path.c_str(), line.c_str());
      int checks = 0;
      for (size_t i = 0; i < result.checks.size(); ++i)
        checks = std::max(checks, report_checks(panes.panes[i].label.empty() ? scene_path : scene_path + " [" + panes.panes[i].label + "]",
                                                result.checks[i]));
      return result.passed ? checks : kExitCheckFailed;
    }
    if (*simulate) {
      if (trace.bodies_path.empty() && trace.contacts_path.empty() && trace.world_path.empty())
        throw std::invalid_argument("simulate writes CSV: give --trace, --contacts or --world (or several)");
      demos::Scene scene = load(scene_path, simulate_settings, false);  // numbers only: no TeX needed
      // The file's own values, not a pane of its [compare]: the checks about a pane do not apply.
      std::erase_if(scene.checks, [](const demos::CheckSpec& spec) { return spec.pane != 0; });
      std::vector<demos::CheckResult> checks;
      const long steps = demos::simulate_scene(scene, trace, &checks);
      std::fprintf(stderr, "simulated %ld steps of %s\n", steps, scene_path.c_str());
      return report_checks(scene_path, checks);
    }
    if (*check) {
      const demos::Scene scene = load(scene_path, check_settings);
      if (!scene.compare.values.empty()) demos::load_variants(scene_path, check_settings, scene.compare);  // each pane's values
      std::printf("%s: fine, %zu bodies, %.1f s, %zu checks\n", scene_path.c_str(), scene.bodies.size(), scene.duration,
                  scene.checks.size());
      if (!check_simulate) return 0;
      if (scene.compare.values.empty()) {
        std::vector<demos::CheckResult> checks;
        demos::simulate_scene(scene, demos::TraceOptions{}, &checks);
        return report_checks(scene_path, checks);
      }
      int exit_code = 0;  // each pane of the comparison, with its checks
      const std::vector<demos::Scene> panes = demos::load_variants(scene_path, check_settings, scene.compare);
      for (size_t i = 0; i < panes.size(); ++i) {
        std::vector<demos::CheckResult> checks;
        demos::simulate_scene(panes[i], demos::TraceOptions{}, &checks);
        exit_code = std::max(exit_code, report_checks(scene_path + " [" + scene.compare.labels[i] + "]", checks));
      }
      return exit_code;
    }
  } catch (const std::exception& error) {
    return report(error);
  }
  return 0;
}
