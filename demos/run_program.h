// The `impulse` program as a function: main() calls it, and the tests call it in-process.
#pragma once

namespace impulse::demos {

// Reads the command line (argv[0] the program's name), runs the command it names and returns
// the exit code (program.h); --help and its like print and return 0. Installs the interrupt
// handlers (interrupts.h) before any command runs.
int run_program(int argc, char** argv);

}  // namespace impulse::demos
