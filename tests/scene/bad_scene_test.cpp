// Bad scenes (tests/bad_scenes/, one file each): each is refused with exactly the message in
// tests/bad_scenes/expected.tsv, or, when it is odd but allowed, gets exactly that warning; a
// directory and a missing file are refused too. Run from the repository root.
#include "demos/scene/scene_compare.h"
#include "demos/scene/scene_file.h"
#include "demos/scene/scene_world.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>

namespace impulse {
namespace {

namespace fs = std::filesystem;

// What loading `path` says: the error, or else the first warning, or else "fine".
std::string verdict(const std::string& path) {
  try {
    const demos::SceneFile file(path);
    const demos::Scene scene = file.scene();
    if (!scene.compare.values.empty()) demos::load_variants(file, {}, scene.compare);  // each pane's value
    const std::vector<std::string> warnings = demos::start_warnings(scene);
    return warnings.empty() ? "fine" : warnings.front();
  } catch (const demos::SceneError& error) {
    return error.what();
  }
}

long peak_resident_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// ... each within a second and 64 MiB (too_many.toml's lattice of 10^9 boxes is refused before
// anything is allocated).
TEST(BadScenes, EachGetsExactlyItsMessage) {
  std::ifstream expected("tests/bad_scenes/expected.tsv");
  ASSERT_TRUE(expected) << "run from the repository root";
  const long resident_before = peak_resident_kib();
  int cases = 0;
  for (std::string line; std::getline(expected, line); ++cases) {
    const size_t tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    const std::string path = "tests/bad_scenes/" + line.substr(0, tab);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(verdict(path), line.substr(tab + 1)) << path;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0) << path << ": s";
    EXPECT_LT(peak_resident_kib() - resident_before, 64 * 1024) << path << ": KiB more at the peak";
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
