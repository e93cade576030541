// The commands of the `impulse` program. Each group of commands is a file of its own
// (render_commands.cpp, catalogue_commands.cpp, simulate_commands.cpp, verify_command.cpp) with one
// function that adds its subcommands, their options and what they run; run_program.cpp calls each
// once. A new command is a new file, its add_ function declared below and called there.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace impulse::demos {

// What every command gets besides its own options.
struct Invocation {
  bool progress = false;               // a progress bar on stderr (not -q; a terminal, or --progress)
  std::vector<std::string> arguments;  // the command line, without the program's name (catalogue --jobs)
};

// A command's work once its options are read; returns the exit code (program.h). Throws what
// report() turns into one.
using CommandRun = std::function<int(const Invocation&)>;

// The subcommands of the program's command line, and what each runs.
class Commands {
 public:
  explicit Commands(CLI::App& app) : app_(app) {}

  // A subcommand. Its options go to the returned CLI::App, bound to storage that `run` holds
  // (a shared_ptr it captures), so that they live as long as the command.
  CLI::App* add(const std::string& name, const std::string& description, CommandRun run);

  // Runs the subcommand the parsed command line chose; its exit code.
  int run(const Invocation& invocation) const;

 private:
  CLI::App& app_;
  std::vector<std::pair<CLI::App*, CommandRun>> commands_;
};

// The command groups, each in its file.
void add_render_commands(Commands& commands);     // render, compare
void add_catalogue_commands(Commands& commands);  // catalogue, gallery
void add_simulate_commands(Commands& commands);   // simulate, check
void add_verify_command(Commands& commands);      // verify

}  // namespace impulse::demos
