#include "tex/child_run.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

extern char** environ;

namespace impulse::tex {

namespace {

// This process's environment with `changes` (NAME=VALUE) over it.
std::vector<std::string> environment_with(const std::vector<std::string>& changes) {
  std::vector<std::string> result;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string text = *entry;
    bool changed = false;
    for (const std::string& change : changes) changed = changed || text.compare(0, change.find('=') + 1, change, 0, change.find('=') + 1) == 0;
    if (!changed) result.push_back(text);
  }
  result.insert(result.end(), changes.begin(), changes.end());
  return result;
}

}  // namespace

ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& directory, const std::string& log_path,
                       double seconds, const ChildOptions& options) {
  ChildOutcome outcome;
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> environment = environment_with(options.environment);
  std::vector<char*> envp;
  for (std::string& entry : environment) envp.push_back(entry.data());
  envp.push_back(nullptr);
  // A pipe closed on exec tells the parent whether exec worked: the child writes errno into it.
  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0) {
    outcome.error = std::string("cannot make a pipe: ") + std::strerror(errno);
    return outcome;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    outcome.error = std::string("cannot start a process: ") + std::strerror(errno);
    close(report[0]);
    close(report[1]);
    return outcome;
  }
  if (pid == 0) {  // the child: only async-signal-safe calls until exec
    setpgid(0, 0);  // its own process group, so a kill reaches anything it started
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || chdir(directory.c_str()) != 0) {
      const int code = errno;
      (void)!write(report[1], &code, sizeof code);
      _exit(127);
    }
    dup2(in, 0);
    dup2(out, 1);
    dup2(out, 2);
    if (options.before_exec) {
      if (const int code = options.before_exec(); code != 0) {
        (void)!write(report[1], &code, sizeof code);
        _exit(127);
      }
    }
    execvpe(args[0], args.data(), envp.data());
    const int code = errno;
    (void)!write(report[1], &code, sizeof code);
    _exit(127);
  }
  close(report[1]);
  int exec_errno = 0;
  const bool exec_failed = read(report[0], &exec_errno, sizeof exec_errno) == sizeof exec_errno;
  close(report[0]);

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) break;
    if (std::chrono::steady_clock::now() > deadline) {
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      outcome.started = true;
      outcome.timed_out = true;
      return outcome;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (exec_failed) {
    outcome.error = argv[0] + ": " + std::strerror(exec_errno);
    return outcome;
  }
  outcome.started = true;
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  outcome.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return outcome;
}

}  // namespace impulse::tex
