#include "demos/response/compile_sandbox.h"

#include "demos/response/landlock.h"
#include "demos/response/sandbox_limits.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace impulse::workshop {

namespace {

// Each ':'-separated entry of `list`, made canonical, where it exists.
void add_existing(std::set<std::string>& paths, const std::string& list) {
  std::stringstream entries(list);
  for (std::string entry; std::getline(entries, entry, ':');) {
    std::error_code error;
    const fs::path real = fs::canonical(entry, error);
    if (!error) paths.insert(real.string());
  }
}

// What `compiler ARGS` prints, run in a temporary directory of its own.
std::string compiler_says(const std::string& compiler, const std::vector<std::string>& arguments) {
  const fs::path directory = fs::temp_directory_path() / ("impulse-toolchain-" + std::to_string(getpid()));
  fs::create_directories(directory);
  std::vector<std::string> argv = {compiler};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  tex::run_child(argv, directory.string(), (directory / "says.log").string(), 30);
  std::ifstream log(directory / "says.log");
  std::ostringstream text;
  text << log.rdbuf();
  std::error_code error;
  fs::remove_all(directory, error);
  return text.str();
}

int set_limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit value{soft, hard};
  return setrlimit(resource, &value) == 0 ? 0 : errno;
}

}  // namespace

std::vector<std::string> toolchain_paths(const std::string& compiler, const std::string& list) {
  static std::mutex mutex;
  static std::map<std::string, std::vector<std::string>> known;
  const std::lock_guard lock(mutex);
  if (const auto found = known.find(compiler); found != known.end()) return found->second;
  if (std::ifstream kept(list); !list.empty() && kept) {
    std::vector<std::string> paths;
    for (std::string line; std::getline(kept, line);)
      if (!line.empty()) paths.push_back(line);
    if (!paths.empty()) return known[compiler] = paths;
  }
  std::set<std::string> paths;
  add_existing(paths, "/usr/bin:/bin:/lib64:/etc/ld.so.cache");
  std::istringstream search(compiler_says(compiler, {"-print-search-dirs"}));
  for (std::string line; std::getline(search, line);) {
    for (const char* key : {"install: ", "programs: =", "libraries: ="})
      if (line.rfind(key, 0) == 0) add_existing(paths, line.substr(std::string(key).size()));
  }
  std::istringstream includes(compiler_says(compiler, {"-E", "-v", "-x", "c++", "/dev/null"}));
  bool listing = false;
  for (std::string line; std::getline(includes, line);) {
    if (line.find("search starts here") != std::string::npos) listing = true;
    else if (line.rfind("End of search list", 0) == 0) listing = false;
    else if (listing && !line.empty() && line[0] == ' ') add_existing(paths, line.substr(1));
  }
  std::error_code error;
  if (const fs::path real = fs::canonical(compiler.find('/') == std::string::npos ? "/usr/bin/" + compiler : compiler, error); !error)
    paths.insert(real.parent_path().string());
  if (!list.empty()) {  // whole or not at all
    const std::string part = list + "." + std::to_string(getpid()) + ".part";
    std::ofstream(part) << [&] {
      std::string text;
      for (const std::string& path : paths) text += path + "\n";
      return text;
    }();
    fs::rename(part, list, error);
  }
  return known[compiler] = std::vector<std::string>(paths.begin(), paths.end());
}

tex::ChildOutcome run_compiler(const CompileJob& job) {
  LandlockRuleset ruleset;
  for (const std::string& path : toolchain_paths(job.argv.front(), job.toolchain_list)) ruleset.allow_reading(path, true);
  for (const std::string& path : job.readable) ruleset.allow_reading(path);
  ruleset.allow_reading_and_writing("/dev/null");
  ruleset.allow_everything(job.build_directory);
  tex::ChildOptions options;
  options.environment = {"TMPDIR=" + job.build_directory};
  options.before_exec = [&ruleset] {
    int error = set_limit(RLIMIT_AS, limits::kCompileMemoryBytes, limits::kCompileMemoryBytes);
    if (error == 0) error = set_limit(RLIMIT_CPU, limits::kCompileCpuSeconds, limits::kCompileCpuSeconds + 1);
    if (error == 0) error = set_limit(RLIMIT_FSIZE, limits::kCompileFileBytes, limits::kCompileFileBytes);
    if (error == 0) error = set_limit(RLIMIT_CORE, 0, 0);
    return error != 0 ? error : ruleset.restrict_self();
  };
  return tex::run_child(job.argv, job.build_directory, job.log_path, limits::kCompileSeconds, options);
}

}  // namespace impulse::workshop
