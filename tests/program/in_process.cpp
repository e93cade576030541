#include "tests/program/in_process.h"

#include "demos/run_program.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impulse::testing {
namespace {

// One of the process's standard streams sent to a file of its own while it lives, then put back.
class Captured {
 public:
  Captured(std::FILE* stream, int fd) : stream_(stream), fd_(fd) {
    char name[] = "/tmp/impulse_in_process_XXXXXX";
    const int file = mkstemp(name);
    if (file < 0) throw std::runtime_error("cannot make a temporary file for the program's output");
    path_ = name;
    std::fflush(stream_);
    saved_ = dup(fd_);
    dup2(file, fd_);
    close(file);
  }
  ~Captured() {
    restore();
    std::remove(path_.c_str());
  }
  Captured(const Captured&) = delete;
  Captured& operator=(const Captured&) = delete;

  std::string text() {
    restore();
    std::ostringstream text;
    text << std::ifstream(path_).rdbuf();
    return text.str();
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stream_);
    dup2(saved_, fd_);
    close(saved_);
    saved_ = -1;
  }
  std::FILE* stream_;
  int fd_;
  int saved_ = -1;
  std::string path_;
};

}  // namespace

ProgramRun run_in_process(const std::vector<std::string>& arguments) {
  std::vector<std::string> words = arguments;
  words.insert(words.begin(), "impulse");  // argv[0], the program's name
  std::vector<char*> argv(words.size() + 1, nullptr);
  std::transform(words.begin(), words.end(), argv.begin(), [](std::string& word) { return word.data(); });
  Captured out(stdout, STDOUT_FILENO);
  Captured err(stderr, STDERR_FILENO);
  ProgramRun run;
  run.exit_code = demos::run_program(int(words.size()), argv.data());
  run.stderr_text = err.text();
  run.stdout_text = out.text();
  return run;
}

}  // namespace impulse::testing
