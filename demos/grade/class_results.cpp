#include "demos/grade/class_results.h"

#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace impulse::workshop {

int StudentResult::passed() const {
  int count = 0;
  for (const CaseResult& result : cases) count += result.passed;
  return count;
}

std::vector<std::string> StudentResult::failed_cases() const {
  std::vector<std::string> names;
  for (const CaseResult& result : cases)
    if (!result.passed) names.push_back(result.name);
  return names;
}

std::string first_message(const std::string& text) {
  std::istringstream lines(text);
  std::string first, useful;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    if (first.empty()) first = line;
    if (line.find(": error:") != std::string::npos || line.find(": fatal error:") != std::string::npos) return line;
    if (useful.empty() && line.find(": In ") == std::string::npos && line.find("does not compile:") == std::string::npos) useful = line;
  }
  return useful.empty() ? first : useful;
}

void write_student_report(const std::string& path, const StudentResult& result) {
  toml::array cases;
  for (const CaseResult& c : result.cases)
    cases.push_back(toml::table{{"name", c.name},         {"title", c.title}, {"law", c.law},   {"expected", c.expected},
                                {"measured", c.measured}, {"passed", c.passed}, {"hint", c.hint}, {"failure", c.failure}});
  const toml::table root{{"student", result.student}, {"file", result.file},       {"compiled", result.compiled},
                         {"message", result.message}, {"details", result.details}, {"case", cases}};
  const std::string part = path + ".part";
  {
    std::ofstream out(part);
    out << root << "\n";
    if (!out.flush()) throw std::runtime_error("cannot write " + part);
  }
  fs::rename(part, path);
}

std::optional<StudentResult> read_student_report(const std::string& path) {
  if (!fs::is_regular_file(path)) return std::nullopt;
  try {
    const toml::table root = toml::parse_file(path);
    StudentResult result;
    result.student = root["student"].value_or(std::string());
    result.file = root["file"].value_or(std::string());
    result.compiled = root["compiled"].value_or(false);
    result.message = root["message"].value_or(std::string());
    result.details = root["details"].value_or(std::string());
    if (const toml::array* cases = root["case"].as_array())
      for (const toml::node& node : *cases) {
        const toml::table& c = *node.as_table();
        result.cases.push_back({c["name"].value_or(std::string()), c["title"].value_or(std::string()), c["law"].value_or(std::string()),
                                c["expected"].value_or(std::string()), c["measured"].value_or(std::string()), c["passed"].value_or(false),
                                c["hint"].value_or(std::string()), c["failure"].value_or(std::string())});
      }
    return result;
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

}  // namespace impulse::workshop
