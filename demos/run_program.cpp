#include "demos/run_program.h"

#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/interrupts.h"

#include <exception>
#include <unistd.h>

namespace impulse::demos {

int run_program(int argc, char** argv) {
  CLI::App app{"impulse: rigid-body collision physics rendered into teaching videos, headless.\n"
               "Scene files are TOML (see README.md, 'Scene files'); videos are H.264 MP4 (BT.709, faststart),\n"
               "written to a temporary of their own (NAME.mp4.PID-N.part) and renamed when complete:\n"
               "renders into one path at once each leave a complete video, the last to finish wins."};
  app.footer(examples_footer("  impulse render assets/scenes/bounce.toml                  # -> out/bounce.mp4\n"
                             "  impulse render assets/scenes/bounce.toml --set world.friction=false -o no_friction.mp4\n"
                             "  impulse compare assets/scenes/bounce.toml --vary world.method=impulse,penalty\n"
                             "  impulse simulate assets/scenes/bounce.toml --trace bodies.csv --world world.csv\n"
                             "  impulse catalogue -o out                                  # every scene of assets/scenes\n"));
  app.require_subcommand(1);
  app.fallthrough();  // -q and --progress also after the subcommand
  bool quiet = false, force_progress = false;
  app.add_flag("-q,--quiet", quiet, "No progress bar on stderr");
  app.add_flag("--progress", force_progress, "A progress bar even when stderr is not a terminal (e.g. in a log)");

  Commands commands(app);
  add_render_command(commands);
  add_compare_command(commands);
  add_catalogue_command(commands);
  add_gallery_command(commands);
  add_simulate_command(commands);
  add_check_command(commands);
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
