#include "tests/support/child_process.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace impulse::testing {
namespace {

std::vector<std::string> child_environment(const ChildSettings& settings) {
  std::vector<std::string> environment;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string variable = *entry;
    bool keep = true;
    for (const std::string& name : settings.unset) keep = keep && variable.rfind(name + "=", 0) != 0;
    if (keep) environment.push_back(variable);
  }
  environment.insert(environment.end(), settings.set.begin(), settings.set.end());
  return environment;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> result;
  for (std::string& text : strings) result.push_back(text.data());
  result.push_back(nullptr);
  return result;
}

}  // namespace

std::string ChildResult::describe() const {
  const std::string how = signal != 0 ? std::string("killed by ") + strsignal(signal) : "exit code " + std::to_string(exit_code);
  return how + "; stderr: " + stderr_text;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const ChildSettings& settings) {
  static std::atomic<int> serial{0};
  stderr_path_ = (std::filesystem::temp_directory_path() /
                  ("impulse_child_" + std::to_string(getpid()) + "_" + std::to_string(serial++) + ".stderr"))
                     .string();
  // Everything the child needs is made before fork(): after it, only async-signal-safe calls.
  std::vector<std::string> arguments = argv;
  std::vector<std::string> environment = child_environment(settings);
  std::vector<char*> argv_pointers = pointers(arguments);
  std::vector<char*> envp_pointers = pointers(environment);
  const rlimit limit{static_cast<rlim_t>(settings.file_size_limit.value_or(0)),
                     static_cast<rlim_t>(settings.file_size_limit.value_or(0))};

  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid_ == 0) {
    const int log = open(stderr_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (log >= 0) dup2(log, STDERR_FILENO);
    const int nothing = open("/dev/null", O_RDONLY);
    if (nothing >= 0) dup2(nothing, STDIN_FILENO);
    if (settings.file_size_limit) setrlimit(RLIMIT_FSIZE, &limit);
    if (!settings.working_directory.empty() && chdir(settings.working_directory.c_str()) != 0) _exit(126);
    execve(argv_pointers[0], argv_pointers.data(), envp_pointers.data());
    _exit(127);
  }
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  std::filesystem::remove(stderr_path_);
}

ChildResult ChildProcess::wait() {
  if (pid_ <= 0) throw std::logic_error("ChildProcess::wait() twice");
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
  }
  pid_ = -1;
  ChildResult result;
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  std::ostringstream text;
  text << std::ifstream(stderr_path_).rdbuf();
  result.stderr_text = text.str();
  return result;
}

}  // namespace impulse::testing
