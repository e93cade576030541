// Helpers for the tests that render whole scenes: a scratch directory, a scene file written from
// text and loaded, and a pixel of a frame.
#pragma once
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "demos/scene/scene_file.h"
#include "render/frame.h"

namespace impulse::testing {

// An empty directory of the system's temporary directory, e.g. scratch("video_test", "decode").
inline std::filesystem::path scratch(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("impulse_" + suite) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The catalogue's scenes by name (assets/scenes/NAME.toml), in order: a parameter per scene.
inline std::vector<std::string> catalogue_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(IMPULSE_SOURCE_DIR) / "assets/scenes"))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// `text` written to DIR/scene.toml and loaded.
inline demos::Scene scene_from(const std::filesystem::path& dir, const std::string& text) {
  const std::filesystem::path path = dir / "scene.toml";
  std::ofstream(path) << text;
  return demos::load_scene(path.string());
}

struct Rgb {
  int r, g, b;
};
inline Rgb pixel(const render::Frame& frame, int x, int y) {
  const uint8_t* p = &frame.rgba[(size_t(y) * frame.width + x) * 4];
  return {p[0], p[1], p[2]};
}

}  // namespace impulse::testing
