// The options render, compare and simulate take for a student's AddCollisionImpulse: --response
// FILE and --time-limit SECONDS. The commands `impulse response` and `impulse grade` are in
// command.h, with the others; all of them are defined in workshop_commands.cpp.
#pragma once
#include "demos/program.h"

#include <CLI/CLI.hpp>

namespace impulse::demos {

// --response FILE.cpp|.so (as --set world.response=FILE, after the command's --set: add it after
// them) and --time-limit SECONDS for each call of its function.
void add_response_options(CLI::App* command, SceneArguments& arguments);

}  // namespace impulse::demos
