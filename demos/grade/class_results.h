// A student's grade in a class's run (`impulse grade FOLDER`): what each submission's own process
// (`impulse grade FILE --class-report REPORT`) writes, in TOML, and the class's process reads back.
#pragma once
#include "demos/grade/grade.h"

#include <optional>
#include <string>
#include <vector>

namespace impulse::workshop {

struct StudentResult {
  std::string student;            // the file's name without .cpp, or its folder's
  std::string file;               // as the class's process named it
  bool compiled = false;          // false: `message` says why it was not graded
  std::string message;            // the first of the compiler's messages, or what else stopped it
  std::string details;            // all that was said (the compiler's messages, up to 16 KiB)
  std::vector<CaseResult> cases;  // in order, when it compiled

  int passed() const;
  int max_score() const { return int(case_names().size()); }
  std::vector<std::string> failed_cases() const;
};

// The first message of the compiler's `text` worth a row: its first line naming an error, else
// its first line that is not "In function ...", else the first line.
std::string first_message(const std::string& text);

// REPORT, written whole or not at all; read back (nothing when it is missing or not a report).
void write_student_report(const std::string& path, const StudentResult& result);
std::optional<StudentResult> read_student_report(const std::string& path);

}  // namespace impulse::workshop
