#include "demos/run_program.h"

#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/interrupts.h"

#include "render/gl_context.h"

#include <cstdlib>
#include <exception>
#include <string>
#include <unistd.h>

#ifndef IMPULSE_COMMIT
#define IMPULSE_COMMIT "unknown"
#endif

namespace impulse::demos {
namespace {

// The program's commit, and what OpenGL draws with here (a context made the way a render makes one).
std::string version_text() {
  std::string text = std::string("impulse (commit ") + IMPULSE_COMMIT + ")\n";
  try {
    const render::GlContext context;
    const render::GlInfo& info = context.info();
    text += std::string("OpenGL: ") + render::gl_backend_name(info.backend) + ", " + info.device + ": " + info.renderer + ", " +
            info.version;
  } catch (const std::exception& error) {
    text += std::string("OpenGL: none works here: ") + error.what();
  }
  return text;
}

}  // namespace

int run_program(int argc, char** argv) {
  CLI::App app{"impulse: rigid-body collision physics rendered into teaching videos, headless.\n"
               "Scene files are TOML (see README.md, 'Scene files'); videos are H.264 MP4 (BT.709, faststart),\n"
               "written to a temporary of their own (NAME.mp4.PID-N.part) and renamed when complete:\n"
               "renders into one path at once each leave a complete video, the last to finish wins."};
  app.footer(examples_footer("  impulse render assets/scenes/bounce.toml                  # -> out/bounce.mp4\n"
                             "  impulse render assets/scenes/bounce.toml --set world.friction=false -o no_friction.mp4\n"
                             "  impulse compare assets/scenes/bounce.toml --vary world.method=impulse,penalty\n"
                             "  impulse simulate assets/scenes/bounce.toml --trace bodies.csv --world world.csv\n"
                             "  impulse catalogue -o out                                  # every scene of assets/scenes\n"
                             "  impulse --gl osmesa render assets/scenes/bounce.toml      # drawn through OSMesa, not EGL\n"));
  app.require_subcommand(1);
  app.fallthrough();  // -q and --progress also after the subcommand
  bool quiet = false, force_progress = false;
  app.add_flag("-q,--quiet", quiet, "No progress bar on stderr");
  app.add_flag("--progress", force_progress, "A progress bar even when stderr is not a terminal (e.g. in a log)");
  // Set in the environment, so that the program's child processes draw the same way.
  app.add_option_function<std::string>("--gl", [](const std::string& name) { setenv("IMPULSE_GL", name.c_str(), 1); },
                                       "OpenGL from: auto (EGL, else OSMesa; default), egl (a GPU, else Mesa's llvmpipe) "
                                       "or osmesa (llvmpipe); also IMPULSE_GL")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  app.add_option_function<int>("--gpu", [](int gpu) { setenv("IMPULSE_GPU", std::to_string(gpu).c_str(), 1); },
                               "Draw on this GPU (EGL device, from 0) or fail; default: the first GPU, else software; "
                               "also IMPULSE_GPU")
      ->check(CLI::Range(0, 255));
  app.set_version_flag("--version", version_text, "The program's commit and what OpenGL draws with here, then exit");

  Commands commands(app);
  add_render_command(commands);
  add_compare_command(commands);
  add_catalogue_command(commands);
  add_gallery_command(commands);
  add_simulate_command(commands);
  add_check_command(commands);
  add_export_command(commands);
  add_preview_command(commands);
  add_verify_command(commands);
  add_response_command(commands);
  add_grade_command(commands);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kExitBadInput;  // --help is no error
  }
  install_interrupt_handlers();
  Invocation invocation;
  invocation.progress = !quiet && (force_progress || isatty(STDERR_FILENO));
  invocation.arguments.assign(argv + 1, argv + argc);
  try {
    return commands.run(invocation);
  } catch (const std::exception& error) {
    return report(error);
  }
}

}  // namespace impulse::demos
