#include "demos/interrupts.h"

#include <csignal>
#include <cstring>
#include <unistd.h>

#include "render/part_file.h"

namespace impulse::demos {
namespace {

extern "C" void on_interrupt(int signal_number) {
  render::remove_unfinished_part_files();
  static const char message[] = "\nimpulse: interrupted; the unfinished video was deleted, earlier videos are as they were\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, message, sizeof message - 1);
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

}  // namespace impulse::demos
