// libFuzzer target: the scene loader and the --set parser (scene_input.h says what an input is).
// A SceneError is the expected answer to a bad input; any other exception, a crash, a hang or a
// sanitizer report is a finding. Built and run by scripts/test.sh (tests/fuzz/README.md).
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "tests/fuzz/scene_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    impulse::fuzz::load_input(impulse::fuzz::split_input(data, size));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fuzz_scene: not a SceneError: %s\n", error.what());
    std::abort();  // libFuzzer saves the input as crash-*
  }
  return 0;
}
