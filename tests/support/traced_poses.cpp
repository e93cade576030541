#include "tests/support/traced_poses.h"

#include <cmath>
#include <fstream>

namespace impulse::testing {

Poses traced_poses(const std::filesystem::path& csv, const std::vector<long>& moments) {
  Poses poses;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    const long ms = std::lround(std::stod(cells[0]) * 1000);
    for (const long moment : moments)
      if (ms == moment) poses[{cells[2], ms}] = {std::stod(cells[3]), std::stod(cells[4]), std::stod(cells[5]), std::stod(cells[6]),
                                                   std::stod(cells[7]), std::stod(cells[8]), std::stod(cells[9])};
  }
  return poses;
}

}  // namespace impulse::testing
