// `impulse simulate` and `impulse check`: a scene's numbers and its checks, without pictures.
#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/grade/workshop_commands.h"
#include "demos/simulate.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace impulse::demos {
namespace {

struct SimulateArguments {
  std::string scene_path;
  TraceOptions trace;
  SceneArguments scene;
};

struct CheckArguments {
  std::string scene_path;
  bool simulate = false;
  SceneArguments scene;
};

int simulate(const SimulateArguments& arguments) {
  const TraceOptions& trace = arguments.trace;
  if (trace.bodies_path.empty() && trace.contacts_path.empty() && trace.world_path.empty())
    throw std::invalid_argument("simulate writes CSV: give --trace, --contacts or --world (or several)");
  Scene scene = load(SceneFile(arguments.scene_path), arguments.scene, false);  // numbers only: no TeX needed
  // The file's own values, not a pane of its [compare]: the checks about a pane do not apply.
  std::erase_if(scene.checks, [](const CheckSpec& spec) { return spec.pane != 0; });
  std::vector<CheckResult> checks;
  const long steps = simulate_scene(scene, trace, &checks);
  std::fprintf(stderr, "simulated %ld steps of %s\n", steps, arguments.scene_path.c_str());
  return report_checks(arguments.scene_path, checks);
}

// "1 check", "2 checks".
std::string checks_count(size_t count) { return std::to_string(count) + (count == 1 ? " check" : " checks"); }

// `check` says the file reads fine; `check --simulate` says so only after its checks, with
// their verdict, so that no "fine" stands above a FAIL.
int check(const CheckArguments& arguments) {
  const std::string& path = arguments.scene_path;
  const SceneFile file(path);
  const Scene scene = load(file, arguments.scene);
  std::vector<Scene> panes;  // each pane's values, checked as the file's are
  if (!scene.compare.values.empty()) {
    panes = load_variants(file, arguments.scene.settings, scene.compare);
    for (const std::string& warning : compare_warnings(panes, scene.compare)) std::fprintf(stderr, "impulse: %s\n", warning.c_str());
  }
  if (!arguments.simulate) {
    std::printf("%s: fine, %zu bodies, %.1f s, %s%s\n", path.c_str(), scene.bodies.size(), scene.duration,
                checks_count(scene.checks.size()).c_str(), scene.checks.empty() ? "" : " (not run: --simulate runs them)");
    return 0;
  }
  int exit_code = 0;
  size_t checked = 0, failed = 0;
  auto run = [&](const Scene& pane, const std::string& label) {  // a pane of the comparison, or the scene
    std::vector<CheckResult> checks;
    simulate_scene(pane, TraceOptions{}, &checks);
    exit_code = std::max(exit_code, report_checks(label, checks));
    checked += checks.size();
    failed += size_t(std::count_if(checks.begin(), checks.end(), [](const CheckResult& c) { return !c.passed; }));
  };
  if (panes.empty()) run(scene, path);
  for (size_t i = 0; i < panes.size(); ++i) run(panes[i], path + " [" + scene.compare.labels[i] + "]");
  if (failed == 0)
    std::printf("%s: fine, %zu bodies, %.1f s, %s pass%s\n", path.c_str(), scene.bodies.size(), scene.duration,
                checks_count(checked).c_str(), checked == 1 ? "es" : "");
  else
    std::printf("%s: %zu of its %zu checks FAIL (%zu bodies, %.1f s)\n", path.c_str(), failed, checked, scene.bodies.size(),
                scene.duration);
  return exit_code;
}

const std::string kSimulateFooter = examples_footer(
    "  impulse simulate assets/scenes/bounce.toml --trace bodies.csv\n"
    "  impulse simulate scene.toml --duration 2 --every 6 --contacts contacts.csv --world world.csv\n"
    "  impulse simulate scene.toml --set world.friction=false --trace no_friction.csv\n");

const std::string kCheckFooter = examples_footer(
    "  impulse check assets/scenes/bounce.toml\n"
    "  impulse check scene.toml --set body[ball].restitution=1.2   # refused: e in [0, 1]\n"
    "  impulse check --simulate assets/scenes/bounce.toml          # its [[check]]s, measured\n");

}  // namespace

void add_simulate_command(Commands& commands) {
  auto arguments = std::make_shared<SimulateArguments>();
  CLI::App* command = commands.add("simulate", "Simulate a scene and write its numbers as CSV, without pictures",
                                   kSimulateFooter, [arguments](const Invocation&) { return simulate(*arguments); });
  TraceOptions& trace = arguments->trace;
  command->add_option("scene", arguments->scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  command->add_option("--duration", trace.duration, "Seconds of simulated time (default: the scene's)")
      ->check(CLI::Range(0.0, 36000.0));
  command->add_option("--every", trace.every, "Write every Nth step (and the last); default 1")->check(CLI::Range(1, 1000000));
  command->add_option("--trace", trace.bodies_path, "CSV: a row per body per step (time, position, orientation, velocities)");
  command->add_option("--contacts", trace.contacts_path,
                      "CSV: a row per contact per step (bodies, point, normal, penetration, impulses)");
  command->add_option("--world", trace.world_path, "CSV: a row per step (energies, linear and angular momentum)");
  add_scene_options(command, arguments->scene);
  add_response_options(command, arguments->scene);  // a student's AddCollisionImpulse
}

void add_check_command(Commands& commands) {
  auto arguments = std::make_shared<CheckArguments>();
  CLI::App* command = commands.add("check", "Read a scene file and report any error in it, without rendering", kCheckFooter,
                                   [arguments](const Invocation&) { return check(*arguments); });
  command->add_option("scene", arguments->scene_path, "Scene file (.toml)")->required();
  command->add_flag("--simulate", arguments->simulate, "Also simulate the scene and report each of its [[check]]s");
  add_scene_options(command, arguments->scene);
}

}  // namespace impulse::demos
