// `impulse render` and `impulse compare`: a scene, or two to four side by side, into a video.
#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/grade/workshop_commands.h"

#include <memory>

namespace impulse::demos {
namespace {

struct RenderArguments {
  std::string scene_path;
  OutputArguments output;
  VideoOverrides overrides;
};

struct CompareArguments {
  std::vector<std::string> scene_paths;
  std::string vary;
  OutputArguments output;
  VideoOverrides overrides;
};

const std::string kRenderFooter = examples_footer(
    "  impulse render assets/scenes/bounce.toml -o out/bounce.mp4\n"
    "  impulse render assets/scenes/bounce.toml --quality low --set body[0].restitution=0.9\n"
    "  impulse render assets/scenes/s4_angular.toml --png frames --frames 0,45,90\n"
    "  impulse render assets/scenes/s4_angular.toml --png stills --at 0.5,1,2   # stills/t_0.500.png ...\n");

const std::string kCompareFooter =
    "\nThe panes share the first scene's camera, video, playback and duration, and the same simulated\n"
    "time; each is labelled with what sets it apart; plots draw every pane's curve in its colour.\n" +
    examples_footer("  impulse compare assets/scenes/bounce.toml --vary world.method=impulse,penalty\n"
                    "  impulse compare assets/scenes/s4_angular.toml --vary world.friction=true,false\n"
                    "  impulse compare a.toml b.toml -o a_vs_b.mp4\n");

}  // namespace

void add_render_command(Commands& commands) {
  auto arguments = std::make_shared<RenderArguments>();
  CLI::App* render = commands.add(
      "render", "Simulate one scene file and write it as an MP4 video (and PNG frames)", kRenderFooter,
      [arguments](const Invocation& run) {
        const RenderOptions options = output_options(arguments->output, default_video_path(arguments->scene_path, "out"));
        return render_one(arguments->scene_path, options, arguments->overrides, run.progress);
      });
  render->add_option("scene", arguments->scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  add_output_options(render, arguments->output, "Video to write (default: out/<scene name>.mp4)");
  add_video_options(render, arguments->overrides);
  add_response_options(render, arguments->overrides.scene_arguments);  // a student's AddCollisionImpulse
}

void add_compare_command(Commands& commands) {
  auto arguments = std::make_shared<CompareArguments>();
  CLI::App* compare = commands.add(
      "compare", "Two to four settings or scenes side by side in one video, one pane each", kCompareFooter,
      [arguments](const Invocation& run) {
        const RenderOptions options =
            output_options(arguments->output, default_comparison_path(arguments->scene_paths, arguments->vary));
        return render_comparison(arguments->scene_paths, arguments->vary, options, arguments->overrides, run.progress);
      });
  compare->add_option("scenes", arguments->scene_paths, "Scene files (.toml): one with --vary, else two to four")
      ->required()
      ->check(CLI::ExistingFile);
  compare->add_option("--vary", arguments->vary, "KEY=V1,V2[,V3[,V4]]: one pane per value of a scene field (as --set writes it)")
      ->type_name("KEY=VALUES");
  add_output_options(compare, arguments->output, "Video to write (default: out/<scene>_<key>.mp4, or out/<a>_vs_<b>.mp4)");
  add_video_options(compare, arguments->overrides);
  add_response_options(compare, arguments->overrides.scene_arguments);
}

}  // namespace impulse::demos
