#include "demos/command.h"

#include "demos/program.h"

namespace impulse::demos {

CLI::App* Commands::add(const std::string& name, const std::string& description, const std::string& footer,
                        CommandRun run) {
  CLI::App* command = app_.add_subcommand(name, description);
  command->footer(footer);
  commands_.emplace_back(command, std::move(run));
  return command;
}

int Commands::run(const Invocation& invocation) const {
  for (const auto& [command, run] : commands_)
    if (command->parsed()) return run(invocation);
  return kExitBadInput;  // unreachable: the command line requires one command
}

}  // namespace impulse::demos
