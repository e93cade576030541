// The `impulse` program run inside the test's own process (demos/run_program.h), as a user's shell
// would run it: its exit code, and what it wrote to stdout and stderr. Faster than a child process,
// and under the sanitizers with the test. What needs a process of its own stays in one
// (tests/support/child_process.h): signals, file-size limits, `catalogue --jobs` (it starts
// /proc/self/exe), the environment llvmpipe reads at its start.
#pragma once
#include "tests/support/child_process.h"

#include <string>
#include <vector>

namespace impulse::testing {

struct ProgramRun : ChildResult {
  std::string stdout_text;
};

// `impulse ARGUMENTS...` (without the program's name). Not for two threads at once: stdout and
// stderr are the process's.
ProgramRun run_in_process(const std::vector<std::string>& arguments);

}  // namespace impulse::testing
