// The `impulse` command line: scene files in, teaching videos out (run_program.h).
#include "demos/run_program.h"

int main(int argc, char** argv) { return impulse::demos::run_program(argc, argv); }
