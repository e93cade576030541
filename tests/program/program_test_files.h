// What the program's tests share: a scratch directory per test, CSV traces read back, files'
// bytes, and two small scenes (a head-on hit, a sliding box).
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace impulse::testing {

namespace fs = std::filesystem;

inline fs::path work_directory() {
  const fs::path dir = fs::temp_directory_path() / ("impulse_program_" + std::to_string(getpid()) + "_" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A CSV file as rows of named columns.
inline std::vector<std::map<std::string, std::string>> read_csv(const fs::path& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(file, line)) {
    std::map<std::string, std::string> row;
    std::stringstream cells(line);
    std::string cell;
    for (size_t i = 0; i < header.size() && std::getline(cells, cell, ','); ++i) row[header[i]] = cell;
    rows.push_back(row);
  }
  return rows;
}

inline double number(const std::map<std::string, std::string>& row, const std::string& column) {
  return std::stod(row.at(column));
}

// The last row of `body` in a --trace file.
inline std::map<std::string, std::string> last_of(const std::vector<std::map<std::string, std::string>>& rows,
                                           const std::string& body) {
  std::map<std::string, std::string> last;
  for (const auto& row : rows)
    if (row.at("body") == "\"" + body + "\"") last = row;
  return last;
}

inline std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

// Two spheres head on in empty space: 1 kg at 3 m/s onto 2 kg at rest, e = 1.
inline constexpr const char* kHeadOn = R"(
[scene]
duration = 2.0
[world]
gravity = [0, 0, 0]
[[body]]
name = "light"
shape = "sphere"
radius = 0.5
mass = 1.0
restitution = 1.0
position = [-2, 0, 0]
velocity = [3, 0, 0]
[[body]]
name = "heavy"
shape = "sphere"
radius = 0.5
mass = 2.0
restitution = 1.0
position = [1, 0, 0]
)";

// A box sliding on the ground: friction stops it; --set world.friction=false lets it slide on.
inline constexpr const char* kSlide = R"(
[scene]
duration = 2.0
[[body]]
name = "ground"
shape = "plane"
friction = 0.5
[[body]]
name = "box"
shape = "box"
size = [1, 1, 1]
position = [0, 0.5, 0]
velocity = [3, 0, 0]
friction = 0.5
)";

}  // namespace impulse::testing
