#include "demos/grade/workshop_commands.h"

#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/program.h"
#include "demos/scene/scene_response.h"
#include "demos/grade/class_grade.h"
#include "demos/grade/class_outputs.h"
#include "demos/grade/grade.h"
#include "demos/grade/grade_report.h"
#include "demos/response/response_build.h"
#include "demos/response/response_child.h"
#include "render/part_file.h"

#include <unistd.h>

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
    "  impulse grade submissions/ --jobs 2 --csv grades.csv --gradescope results/ --junit grades.xml\n"
    "  impulse grade submissions/ --shard 2/4 --reports out/reports   # a Slurm array task (docs/autograders.md)\n"
    "  impulse grade submissions/ --merge-reports out/reports --csv grades.csv   # its last step\n"
    "\nA folder is a class: every *.cpp in it (the student is its name), or the one .cpp of each folder in it\n"
    "(the student is the folder's name), each graded in a process and a sandbox of its own, --jobs at once;\n"
    "a table of student, score and cases failed (or the first message of a file that does not compile).\n"
    "\nExit codes: 0 every case passes; 2 some fail (for a class: a case, or a file that does not compile);\n"
    "1 the file does not compile, or the command line is wrong.";

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
  int jobs = 1;
  std::string shard, csv, gradescope, junit;
  std::string reports, merge_reports;  // a class in shards: each keeps its reports; a last run merges them
  bool regrade = false;  // a class: grade every submission, also those graded before unchanged
  std::string class_report;  // a class's child: its report here, its output beside it (class_grade.h)
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

void write_text(const std::string& path, const std::string& text) {
  if (const fs::path parent = fs::path(path).parent_path(); !parent.empty()) fs::create_directories(parent);
  render::PartFile part(path);
  {
    std::ofstream out(part.part_path(), std::ios::binary);
    out << text;
    if (!out.flush()) throw render::OutputError("cannot write " + path);
  }
  part.commit();
}

// --csv, --gradescope and --junit, of one student (Gradescope's results.json in DIR) or of a class
// (DIR/STUDENT/results.json).
void write_outputs(const GradeArguments& options, const std::vector<StudentResult>& results, bool one) {
  if (!options.csv.empty()) write_text(options.csv, class_csv(results));
  if (!options.junit.empty()) write_text(options.junit, junit_xml(options.file, results));
  if (!options.gradescope.empty())
    for (const StudentResult& result : results)
      write_text((fs::path(options.gradescope) / (one ? "" : result.student) / "results.json").string(), gradescope_json(result));
}

// A file that did not build, as a row: the first of the compiler's messages (or the refusal), the
// file named as it was given rather than by the absolute path the compiler uses.
void not_built(StudentResult& result, const BuildError& error) {
  std::string text = error.what();
  const std::string absolute = fs::absolute(result.file).lexically_normal().string();
  for (size_t at = text.find(absolute); at != std::string::npos; at = text.find(absolute, at + result.file.size()))
    text.replace(at, absolute.size(), result.file);
  result.details = text;
  result.message = text.find(" does not compile:") != std::string::npos ? "does not compile: " + first_message(text) : first_message(text);
}

// A class's child: the grade of one file into its report, whatever happens; its own output and
// the student's into the report's log, out of the class's table.
int run_class_child(const GradeArguments& options) {
  const std::string log = options.class_report + ".log";
  if (FILE* out = std::freopen(log.c_str(), "w", stderr); out != nullptr) dup2(fileno(out), STDOUT_FILENO);
  StudentResult result;
  result.file = options.file;
  try {
    result.cases = grade(response_for(options.file, options.time_limit), options.only, response_source(options.file));
    result.compiled = true;
  } catch (const BuildError& error) {
    not_built(result, error);
  }
  write_student_report(options.class_report, result);
  return !result.compiled ? kExitBadInput : result.passed() < int(result.cases.size()) ? kExitCheckFailed : 0;
}

int run_class(const GradeArguments& options) {
  if (options.json || !options.video_directory.empty())
    throw std::invalid_argument("a class (" + options.file + ") is written with --csv, --gradescope or --junit; --json and --video are for one file");
  ClassRun run;
  run.jobs = options.jobs;
  run.time_limit = options.time_limit;
  if (!options.shard.empty()) demos::read_shard(options.shard, run.shard, run.shards);
  run.reports = options.reports;
  if (!options.regrade) run.kept = kept_results_directory();
  const std::vector<Submission> submissions = find_submissions(options.file);
  const std::vector<StudentResult> results =
      options.merge_reports.empty() ? grade_class(submissions, run) : merge_class(submissions, options.merge_reports);
  std::fputs(class_table(options.file, results).c_str(), stdout);
  std::fflush(stdout);
  write_outputs(options, results, false);
  for (const StudentResult& result : results)
    if (!result.compiled || result.passed() < result.max_score()) return kExitCheckFailed;
  return 0;
}

int run_grade(const GradeArguments& options, bool progress) {
  if (!options.class_report.empty()) return run_class_child(options);
  if (fs::is_directory(options.file)) return run_class(options);
  if (!options.shard.empty() || !options.reports.empty() || !options.merge_reports.empty())
    throw std::invalid_argument("--shard, --reports and --merge-reports are for a class's folder, not one file");
  StudentResult student;
  student.student = fs::path(options.file).stem().string();
  student.file = options.file;
  physics::OutsideResponseMaker response;
  try {
    response = response_for(options.file, options.time_limit);
  } catch (const BuildError& error) {
    // An autograder's outputs say so too (Gradescope shows the compiler's messages), then the error as ever.
    not_built(student, error);
    write_outputs(options, {student}, true);
    throw;
  }
  const std::vector<CaseResult> results = grade(response, options.only, response_source(options.file));
  std::fputs((options.json ? grade_json(options.file, results) : grade_table(options.file, results)).c_str(), stdout);
  std::fflush(stdout);
  if (!options.video_directory.empty())
    for (const std::string& video : write_failure_videos(options.video_directory, options.file, response, results, progress))
      std::fprintf(stderr, "wrote %s\n", video.c_str());
  student.compiled = true;
  student.cases = results;
  write_outputs(options, {student}, true);
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
  command->add_option("file", arguments->file, "The C++ file (.cpp or a built .so), 'reference', or a class's folder")->required();
  command->add_flag("--json", arguments->json, "The results as JSON on stdout, instead of the table");
  command->add_option("--only", arguments->only, "One case, by its exact name (head_on_equal_e0.7, stack, ...)")->check(CLI::IsMember(case_names()));
  command->add_option("--video", arguments->video_directory, "Write DIR/CASE.mp4 for each failed case: yours beside the reference")
      ->type_name("DIR");
  command->add_option("--time-limit", arguments->time_limit, "Seconds each call may take (default 2)")->check(CLI::Range(0.01, 600.0));
  command->add_option("--jobs", arguments->jobs, "A class: submissions graded at once, each in a process of its own (default 1)")
      ->check(CLI::Range(1, 256));
  command->add_option("--shard", arguments->shard, "A class: K/N, only every Nth submission in name order, from the Kth (array jobs)");
  command->add_option("--csv", arguments->csv, "Also write the grades as CSV: a row per student, a column per case")->type_name("FILE");
  command->add_option("--gradescope", arguments->gradescope,
                      "Also write Gradescope's results.json: DIR/results.json for a file, DIR/STUDENT/results.json for a class")
      ->type_name("DIR");
  command->add_option("--junit", arguments->junit, "Also write JUnit XML: a test suite per student, a test per case")->type_name("FILE");
  command->add_option("--reports", arguments->reports, "A class: keep each student's result in DIR (for --merge-reports)")
      ->type_name("DIR");
  command->add_flag("--regrade", arguments->regrade,
                    "A class: grade every submission again, also those unchanged since they were graded (their results are kept by "
                    "the file's text, this program and the time limit)");
  command->add_option("--merge-reports", arguments->merge_reports,
                      "A class: grade nothing; the table and outputs from the results that shards kept in DIR (--reports)")
      ->type_name("DIR");
  command->add_option("--class-report", arguments->class_report, "")->group("");  // one submission of a class (class_grade.h)
}

}  // namespace impulse::demos
