// Runs a program as a child process in a directory, with a time limit: what the typesetter needs to
// run latex and dvisvgm without a shell, and without waiting forever on a TeX loop.
#pragma once
#include <string>
#include <vector>

namespace impulse::tex {

struct ChildOutcome {
  bool started = false;    // false: the program could not be run (not installed: see `error`)
  bool timed_out = false;  // killed at the time limit, with its process group
  int exit_code = -1;      // when it exited by itself
  std::string error;       // why it did not start
};

// Runs argv[0] (looked up in PATH) in `directory`, standard input from /dev/null and standard
// output and error into `log_path`. Waits at most `seconds`, then kills it.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& directory, const std::string& log_path,
                       double seconds);

}  // namespace impulse::tex
