#include "demos/grade/listing_code.h"

#include <cctype>
#include <sstream>

namespace impulse::workshop {

namespace {

// The line without its comment (// or #) and without blanks.
std::string code_of(const std::string& line) {
  std::string code;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '#' || line.compare(i, 2, "//") == 0) break;
    if (!std::isspace(static_cast<unsigned char>(line[i]))) code += line[i];
  }
  return code;
}

}  // namespace

int hack_fix_line(const std::string& source) {
  std::istringstream lines(source);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const std::string code = code_of(line);
    const size_t assigned = code.find('=');
    if (assigned == std::string::npos || code.find("jn") == std::string::npos || code.find('/') != std::string::npos) continue;
    const std::string value = code.substr(assigned + 1);
    const size_t at = value.find("penetration");
    if (at == std::string::npos) continue;
    // The penetration times a number, on either side of it.
    const bool number_after = value.compare(at + 11, 1, "*") == 0 && at + 12 < value.size() && std::isdigit(static_cast<unsigned char>(value[at + 12]));
    const bool number_before = at >= 2 && value[at - 1] == '*' && (std::isdigit(static_cast<unsigned char>(value[at - 2])) || value[at - 2] == 'f');
    if (number_after || number_before) return number;
  }
  return 0;
}

}  // namespace impulse::workshop
