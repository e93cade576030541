// Runs a program as a child process in a directory, with a time limit: what the typesetter needs to
// run latex and dvisvgm without a shell, and without waiting forever on a TeX loop.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace impulse::tex {

struct ChildOutcome {
  bool started = false;    // false: the program could not be run (not installed: see `error`)
  bool timed_out = false;  // killed at the time limit, with its process group
  int exit_code = -1;      // when it exited by itself (128 + the signal when one ended it)
  int signal = 0;          // the signal that ended it, if one did
  std::string error;       // why it did not start
};

struct ChildOptions {
  std::vector<std::string> environment;  // NAME=VALUE, over this process's environment
  // Runs in the child between fork and exec (limits, a sandbox): async-signal-safe calls only.
  // Returns 0, or an errno: the child then does not start, and `error` says why.
  std::function<int()> before_exec;
};

// Runs argv[0] (looked up in PATH) in `directory`, standard input from /dev/null and standard
// output and error into `log_path`. Waits at most `seconds`, then kills it.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& directory, const std::string& log_path,
                       double seconds, const ChildOptions& options = {});

}  // namespace impulse::tex
