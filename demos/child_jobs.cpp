#include "demos/child_jobs.h"

#include "demos/interrupts.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>

extern char** environ;

namespace impulse::demos {
namespace {

pid_t spawn_self(const std::vector<std::string>& arguments) {
  std::vector<std::string> words{"/proc/self/exe"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), environ);
  if (error != 0) throw std::runtime_error(std::string("cannot start a child process: ") + std::strerror(error));
  watch_child(pid);
  return pid;
}

int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 4;
}

}  // namespace

int run_child_jobs(const std::vector<std::vector<std::string>>& jobs, int parallel,
                   const std::function<void(size_t)>& started, const std::function<void(size_t, int)>& ended) {
  std::map<pid_t, size_t> running;  // child -> its job
  size_t next = 0;
  int worst = 0;
  while (next < jobs.size() || !running.empty()) {
    if (next < jobs.size() && int(running.size()) < std::max(parallel, 1)) {
      started(next);
      running[spawn_self(jobs[next])] = next;
      ++next;
      continue;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("waiting for a child process: ") + std::strerror(errno));
    }
    const auto job = running.find(pid);
    if (job == running.end()) continue;
    forget_child(pid);
    const int code = exit_code_of(status);
    worst = std::max(worst, code);
    ended(job->second, code);
    running.erase(job);
  }
  return worst;
}

}  // namespace impulse::demos
