// The program's workshop commands: `impulse response` (where the header is; build and try a
// file) and `impulse grade` (the cases of grade.h), and the options render, compare and simulate
// take for a student's AddCollisionImpulse: --response FILE and --time-limit SECONDS.
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace impulse::workshop {

// --response FILE.cpp|.so: as --set world.response=FILE, after the command's own --set (so add it
// after them); --time-limit SECONDS for each call of it.
void add_response_options(CLI::App* command, std::vector<std::string>& settings);

class WorkshopCommands {
 public:
  explicit WorkshopCommands(CLI::App& app);  // its options are bound to this object: keep it where it is
  WorkshopCommands(const WorkshopCommands&) = delete;
  WorkshopCommands& operator=(const WorkshopCommands&) = delete;
  bool chosen() const;            // after parsing: was `response` or `grade` the command?
  int run(bool progress) const;   // its exit code

 private:
  struct Options {
    std::string file, output, only, video_directory;
    bool include_directory = false, json = false;
    double time_limit = 2;
  };
  int run_response() const;
  int run_grade(bool progress) const;

  CLI::App* response_ = nullptr;
  CLI::App* grade_ = nullptr;
  Options response_options_, grade_options_;
};

}  // namespace impulse::workshop
