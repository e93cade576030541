// Runs a program in a child process as a user's shell would, for tests of crashes, exit codes,
// signals and resource limits: its stderr kept, its environment and file-size limit chosen.
#pragma once
#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace impulse::testing {

struct ChildSettings {
  std::vector<std::string> unset;       // variable names removed from this process's environment
  std::vector<std::string> set;         // NAME=VALUE added after that
  std::optional<long> file_size_limit;  // bytes (RLIMIT_FSIZE), as `ulimit -f` sets it
  std::string working_directory;        // empty: this process's
};

struct ChildResult {
  int exit_code = -1;   // when it exited
  int signal = 0;       // when a signal ended it
  std::string stderr_text;

  bool succeeded() const { return signal == 0 && exit_code == 0; }
  std::string describe() const;  // "exit code 3; stderr: ..." or "killed by Aborted; stderr: ..."
};

class ChildProcess {
 public:
  // Starts `argv[0]` (a path) with `argv`. Throws std::runtime_error if it cannot.
  ChildProcess(const std::vector<std::string>& argv, const ChildSettings& settings = {});
  ~ChildProcess();  // kills and reaps a child still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  ChildResult wait();  // once

 private:
  pid_t pid_ = -1;
  std::string stderr_path_;
};

inline ChildResult run_child(const std::vector<std::string>& argv, const ChildSettings& settings = {}) {
  return ChildProcess(argv, settings).wait();
}

}  // namespace impulse::testing
