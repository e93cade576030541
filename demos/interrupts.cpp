#include "demos/interrupts.h"

#include <csignal>
#include <cstring>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "render/part_file.h"

namespace impulse::demos {
namespace {

// Plain atomics only: the handler reads them.
constexpr int kMostChildren = 64;
volatile sig_atomic_t children[kMostChildren] = {};

extern "C" void on_interrupt(int signal_number) {
  for (int i = 0; i < kMostChildren; ++i)
    if (children[i] > 0) kill(pid_t(children[i]), signal_number);
  for (int i = 0; i < kMostChildren; ++i)
    if (children[i] > 0) waitpid(pid_t(children[i]), nullptr, 0);
  static const char deleted[] = "\nimpulse: interrupted; the unfinished output was deleted, earlier outputs are as they were\n";
  static const char stopped[] = "\nimpulse: interrupted\n";
  [[maybe_unused]] const ssize_t written = render::remove_unfinished_part_files() > 0 ? write(STDERR_FILENO, deleted, sizeof deleted - 1)
                                                                                      : write(STDERR_FILENO, stopped, sizeof stopped - 1);
  std::signal(signal_number, SIG_DFL);
  raise(signal_number);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal_number, &action, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
}

void watch_child(int pid) {
  for (int i = 0; i < kMostChildren; ++i)
    if (children[i] == 0) {
      children[i] = pid;
      return;
    }
  throw std::logic_error("more than 64 child processes at once");
}

void forget_child(int pid) {
  for (int i = 0; i < kMostChildren; ++i)
    if (children[i] == pid) children[i] = 0;
}

}  // namespace impulse::demos
