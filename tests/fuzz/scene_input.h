// One fuzz input through the scene loader and the --set parser, shared by the libFuzzer target
// (fuzz_scene.cpp) and the replay of tests/fuzz/regressions/ (fuzz_regressions_test.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace impulse::fuzz {

// An input is either a scene file's text, or --set arguments, one a line, then a line "%%", then
// the text: "world.friction=false\nbody[0].mass=2\n%%\n[[body]]\n...".
struct SceneInput {
  std::vector<std::string> settings;
  std::string text;
};
SceneInput split_input(const uint8_t* data, size_t size);

// Loads the input's scene through impulse::demos::load_scene (the text written to an in-memory
// file). Returns true when it loaded, false when it threw SceneError (a bad input, refused as it
// should be); any other exception propagates, and is a finding.
bool load_input(const SceneInput& input);

}  // namespace impulse::fuzz
