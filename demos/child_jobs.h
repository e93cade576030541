// Commands run as child processes of this program, at most `parallel` at a time (impulse catalogue
// --jobs N): each scene in a process of its own, so that one that fails or crashes takes no other
// with it, and an interrupt reaches every running child (interrupts.h).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace impulse::demos {

// Runs `/proc/self/exe` with each argument list, in order, `parallel` at a time. `started(i)` and
// `ended(i, exit_code)` are called in this process as job i starts and ends. Returns the largest
// exit code (a child killed by signal s counts as 128 + s). Throws if a child cannot be started.
int run_child_jobs(const std::vector<std::vector<std::string>>& jobs, int parallel,
                   const std::function<void(size_t)>& started, const std::function<void(size_t, int)>& ended);

}  // namespace impulse::demos
