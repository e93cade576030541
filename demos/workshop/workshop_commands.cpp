#include "demos/workshop/workshop_commands.h"

#include "demos/command.h"
#include "demos/program.h"
#include "demos/scene/scene_response.h"
#include "demos/workshop/grade.h"
#include "demos/workshop/grade_report.h"
#include "demos/workshop/response_build.h"
#include "demos/workshop/response_child.h"
#include "render/part_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

namespace fs = std::filesystem;

namespace impulse::demos {

using namespace impulse::workshop;

namespace {

constexpr const char* kResponseFooter =
    "\nYour file defines listing 1's function, as the workshop prints it:\n"
    "  static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint,\n"
    "                                  const Vector3& normal, float penetration)\n"
    "impulse compiles it after impulse/workshop.h (RigidBody, Vector3, Matrix4, Dot, Cross, Normalize,\n"
    "Transform, DBG_CHECKVECTOR, TimeStep) with $CXX or c++, keeps the result by its content's hash in\n"
    "$IMPULSE_RESPONSE_CACHE (else $XDG_CACHE_HOME/impulse/responses), and runs it in a process of its own:\n"
    "a crash, an endless loop or a NaN ends the run with a report, never impulse. There it may compute and\n"
    "print, nothing else: reading or writing files, the network, starting programs, more than 512 MiB of\n"
    "memory are refused and reported (its sandbox: the last line of `impulse response FILE`).\n"
    "\nExamples:\n"
    "  impulse response --include-dir                     # for your editor: -I$(impulse response --include-dir)\n"
    "  impulse response mine.cpp                          # does it compile, and run?\n"
    "  impulse response mine.cpp -o mine.so               # built, to pass as --response mine.so\n"
    "  impulse render assets/scenes/bounce.toml --response mine.cpp\n"
    "  impulse compare assets/scenes/bounce.toml --vary world.response=mine.cpp,reference\n"
    "\nExit codes: 0 it compiles and runs; 1 it does not compile (the compiler's messages above) or the\n"
    "command line is wrong; 2 it compiles, but crashed, looped or made a NaN when called.";

constexpr const char* kGradeFooter =
    "\nEach case is a small scene and a law: head-on hits at e = 0, 0.7 and 1 with equal and unequal\n"
    "masses (eq. 5 and 7), an off-centre hit that must spin (eq. 11-14), an oblique hit (Coulomb), balls\n"
    "resting on the ground (no jiggle, no sinking), a box sliding with and without friction, and two boxes\n"
    "stacked. The reference (listing 1 corrected) passes every case; `impulse grade reference` shows it.\n"
    "\nExamples:\n"
    "  impulse grade mine.cpp\n"
    "  impulse grade mine.cpp --only head_on_equal_e0.7 --video out/grade   # out/grade/head_on_equal_e0.7.mp4\n"
    "  impulse grade mine.cpp --json > grade.json\n"
    "\nExit codes: 0 every case passes; 2 some fail; 1 the file does not compile, or the command line is wrong.";

// A path as a TOML string, for --set.
std::string toml_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// The response a command's FILE names: "reference" is the engine's own page (no maker).
physics::OutsideResponseMaker response_for(const std::string& file, double time_limit) {
  if (file == "reference") return {};
  return child_response_maker(build_response(file).shared_object, file, time_limit);
}

}  // namespace

void add_response_options(CLI::App* command, SceneArguments& arguments) {
  std::vector<std::string>& settings = arguments.settings;
  command->add_option_function<std::string>(
             "--response", [&settings](const std::string& file) { settings.push_back("world.response=" + toml_string(file)); },
             "A C++ file defining listing 1's AddCollisionImpulse (or a .so from `impulse response -o`), run in place of "
             "the workshop method's page; 'reference' for listing 1 corrected (see `impulse response --help`)")
      ->type_name("FILE");
  command->add_option_function<double>("--time-limit", [](double seconds) { demos::set_response_time_limit(seconds); },
                                       "Seconds each call of --response's function may take (default 2)")
      ->check(CLI::Range(0.01, 600.0));
}

namespace {

struct ResponseArguments {
  std::string file, output;
  bool include_directory = false;
  double time_limit = kDefaultTimeLimit;
};

struct GradeArguments {
  std::string file, only, video_directory;
  bool json = false;
  double time_limit = kDefaultTimeLimit;
};

int run_response(const ResponseArguments& options) {
  if (options.include_directory) {
    std::printf("%s\n", include_directory().c_str());
    return 0;
  }
  if (options.file.empty())
    throw std::invalid_argument("give a file to build (impulse response mine.cpp), or --include-dir for the header's directory (" +
                                include_directory() + ")");
  const BuiltResponse built = build_response(options.file);
  std::fprintf(stderr, "%s: compiles (%s%s)\n", options.file.c_str(), built.compiled ? "built: " : "cached: ", built.shared_object.c_str());
  if (!options.output.empty()) {
    render::PartFile part(options.output);
    fs::copy_file(built.shared_object, part.part_path(), fs::copy_options::overwrite_existing);
    part.commit();
    std::fprintf(stderr, "wrote %s\n", options.output.c_str());
  }
  // Its sandbox, then one case, to see that it loads, returns and keeps its numbers finite.
  std::string sandbox;
  try {
    ChildResponse probe(built.shared_object, options.file, options.time_limit);
    probe.start();
    sandbox = probe.sandbox();
  } catch (const physics::ResponseFailure& failure) {
    std::fprintf(stderr, "impulse: %s\n", failure.what());
    return kExitCheckFailed;
  }
  const CaseResult trial = grade_case("head_on_unequal_e0.7", child_response_maker(built.shared_object, options.file, options.time_limit));
  if (!trial.failure.empty()) {
    std::fprintf(stderr, "impulse: %s\n  hint: %s\n", trial.failure.c_str(), trial.hint.c_str());
    return kExitCheckFailed;
  }
  std::fprintf(stderr, "%s: runs (a head-on hit: %s); `impulse grade %s` holds it to the laws\n", options.file.c_str(),
               trial.measured.c_str(), options.file.c_str());
  std::fprintf(stderr, "its sandbox: %s\n", sandbox.c_str());
  return 0;
}

int run_grade(const GradeArguments& options, bool progress) {
  const physics::OutsideResponseMaker response = response_for(options.file, options.time_limit);
  const std::vector<CaseResult> results = grade(response, options.only);
  std::fputs((options.json ? grade_json(options.file, results) : grade_table(options.file, results)).c_str(), stdout);
  std::fflush(stdout);
  if (!options.video_directory.empty())
    for (const std::string& video : write_failure_videos(options.video_directory, options.file, response, results, progress))
      std::fprintf(stderr, "wrote %s\n", video.c_str());
  for (const CaseResult& result : results)
    if (!result.passed) return kExitCheckFailed;
  return 0;
}

}  // namespace

void add_response_command(Commands& commands) {
  auto arguments = std::make_shared<ResponseArguments>();
  CLI::App* command = commands.add("response", "Where impulse/workshop.h is, and build and try a student's AddCollisionImpulse",
                                   kResponseFooter, [arguments](const Invocation&) { return run_response(*arguments); });
  command->add_option("file", arguments->file, "The C++ file (.cpp) with AddCollisionImpulse");
  command->add_flag("--include-dir", arguments->include_directory, "Print the directory of impulse/workshop.h and stop");
  command->add_option("-o,--output", arguments->output, "Also write the built shared object here (.so)");
  command->add_option("--time-limit", arguments->time_limit, "Seconds the trial call may take (default 2)")->check(CLI::Range(0.01, 600.0));
}

void add_grade_command(Commands& commands) {
  auto arguments = std::make_shared<GradeArguments>();
  CLI::App* command = commands.add("grade", "Hold a student's AddCollisionImpulse to the laws: a table of cases, a hint per failure",
                                   kGradeFooter, [arguments](const Invocation& invocation) { return run_grade(*arguments, invocation.progress); });
  command->add_option("file", arguments->file, "The C++ file (.cpp or a built .so), or 'reference'")->required();
  command->add_flag("--json", arguments->json, "The results as JSON on stdout, instead of the table");
  command->add_option("--only", arguments->only, "One case, by its exact name (head_on_equal_e0.7, stack, ...)")->check(CLI::IsMember(case_names()));
  command->add_option("--video", arguments->video_directory, "Write DIR/CASE.mp4 for each failed case: yours beside the reference")
      ->type_name("DIR");
  command->add_option("--time-limit", arguments->time_limit, "Seconds each call may take (default 2)")->check(CLI::Range(0.01, 600.0));
}

}  // namespace impulse::demos
