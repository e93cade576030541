// Bad scenes (tests/bad_scenes/, one file each): each is refused with exactly the message in
// tests/bad_scenes/expected.tsv, or, when it is odd but allowed, gets exactly that warning; a
// directory and a missing file are refused too. Run from the repository root.
#include "demos/scene/scene_file.h"
#include "demos/scene/scene_world.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace impulse {
namespace {

namespace fs = std::filesystem;

// What loading `path` says: the error, or else the first warning, or else "fine".
std::string verdict(const std::string& path) {
  try {
    const demos::Scene scene = demos::load_scene(path);
    const std::vector<std::string> warnings = demos::start_warnings(scene);
    return warnings.empty() ? "fine" : warnings.front();
  } catch (const demos::SceneError& error) {
    return error.what();
  }
}

TEST(BadScenes, EachGetsExactlyItsMessage) {
  std::ifstream expected("tests/bad_scenes/expected.tsv");
  ASSERT_TRUE(expected) << "run from the repository root";
  int cases = 0;
  for (std::string line; std::getline(expected, line); ++cases) {
    const size_t tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    const std::string path = "tests/bad_scenes/" + line.substr(0, tab);
    EXPECT_EQ(verdict(path), line.substr(tab + 1)) << path;
  }
  // Every file has its line.
  int files = 0;
  for (const auto& entry : fs::directory_iterator("tests/bad_scenes")) files += entry.path().extension() == ".toml";
  EXPECT_EQ(cases, files);
}

TEST(BadScenes, ADirectoryOrAMissingFileIsRefused) {
  const fs::path dir = fs::temp_directory_path() / ("impulse_bad_scenes_" + std::to_string(getpid()));
  fs::create_directories(dir / "scene.toml");
  EXPECT_EQ(verdict((dir / "scene.toml").string()),
            (dir / "scene.toml").string() + ": is a directory, not a scene file (give a .toml file)");
  EXPECT_EQ(verdict((dir / "missing.toml").string()), (dir / "missing.toml").string() + ": no such scene file");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace impulse
