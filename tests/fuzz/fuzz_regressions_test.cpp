// Every input the fuzzer found a fault with (tests/fuzz/regressions/) replayed through the same
// harness as the fuzz target: each must load or be refused with a SceneError, nothing else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/fuzz/scene_input.h"

namespace {

TEST(FuzzRegressions, EveryFoundInputLoadsOrIsRefusedWithASceneError) {
  const std::filesystem::path dir = std::filesystem::path(IMPULSE_SOURCE_DIR) / "tests/fuzz/regressions";
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".input") continue;
    std::ifstream file(entry.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    const std::string data = bytes.str();
    SCOPED_TRACE(entry.path().filename().string());
    EXPECT_NO_THROW(impulse::fuzz::load_input(
        impulse::fuzz::split_input(reinterpret_cast<const uint8_t*>(data.data()), data.size())));
    ++replayed;
  }
  RecordProperty("replayed", replayed);
}

// The input format: --set lines, "%%", the text; without "%%" all of it is the text.
TEST(FuzzRegressions, InputSplitsIntoSettingsAndText) {
  const std::string data = "world.friction=false\nbody[0].mass=2\n%%\n[[body]]\n";
  const auto input = impulse::fuzz::split_input(reinterpret_cast<const uint8_t*>(data.data()), data.size());
  EXPECT_EQ(input.settings, (std::vector<std::string>{"world.friction=false", "body[0].mass=2"}));
  EXPECT_EQ(input.text, "[[body]]\n");
  const std::string plain = "[[body]]\n%%x\n";
  const auto whole = impulse::fuzz::split_input(reinterpret_cast<const uint8_t*>(plain.data()), plain.size());
  EXPECT_TRUE(whole.settings.empty());
  EXPECT_EQ(whole.text, plain);
}

}  // namespace
