// The commands of the `impulse` program. Each command has a function that adds its subcommand,
// its options and what it runs, declared below and defined in the file of its group
// (render_commands.cpp, catalogue_commands.cpp, simulate_commands.cpp, verify_command.cpp);
// run_program.cpp calls each once. A new command is a new file, its add_ function declared below
// and called there.
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

  // A subcommand, its --help ending with `footer`. Its options go to the returned CLI::App, bound
  // to storage that `run` holds (a shared_ptr it captures), so that they live as long as the command.
  CLI::App* add(const std::string& name, const std::string& description, const std::string& footer, CommandRun run);

  // Runs the subcommand the parsed command line chose; its exit code.
  int run(const Invocation& invocation) const;

 private:
  CLI::App& app_;
  std::vector<std::pair<CLI::App*, CommandRun>> commands_;
};

// The commands, by the file that defines them.
void add_render_command(Commands& commands);     // render_commands.cpp
void add_compare_command(Commands& commands);
void add_catalogue_command(Commands& commands);  // catalogue_commands.cpp
void add_gallery_command(Commands& commands);
void add_simulate_command(Commands& commands);   // simulate_commands.cpp
void add_check_command(Commands& commands);
void add_export_command(Commands& commands);     // page_commands.cpp
void add_preview_command(Commands& commands);
void add_verify_command(Commands& commands);     // verify_command.cpp
void add_response_command(Commands& commands);   // workshop/workshop_commands.cpp
void add_grade_command(Commands& commands);

}  // namespace impulse::demos
