#include "demos/grade/class_outputs.h"

#include "demos/html_text.h"

#include <toml++/toml.h>

#include <algorithm>
#include <sstream>

namespace impulse::workshop {

namespace {

std::string joined(const std::vector<std::string>& words, const char* separator) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : separator) + word;
  return text;
}

std::string score_text(const StudentResult& result) {
  return std::to_string(result.compiled ? result.passed() : 0) + "/" + std::to_string(result.max_score());
}

// What the table says of a student beyond the score: the cases failed and the first report of a
// response that failed (a refused system call, a crash), or why it was not graded.
std::string remark(const StudentResult& result) {
  if (!result.compiled) return result.message;
  const std::vector<std::string> failed = result.failed_cases();
  std::string text = failed.size() == result.cases.size() && !failed.empty() ? "every case" : joined(failed, ", ");
  for (const CaseResult& c : result.cases)
    if (!c.failure.empty()) {
      // "FILE: what it did; at step ...": what it did
      std::string report = c.failure.starts_with(result.file + ": ") ? c.failure.substr(result.file.size() + 2) : c.failure;
      report = report.substr(0, report.find("; at step"));
      return text + " (" + report + ")";
    }
  return text;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Text for XML: HTML's entities (&, <, >, "; attributes are in double quotes), and no control
// character XML 1.0 forbids.
std::string xml_text(const std::string& text) {
  std::string allowed;
  for (const char c : text)
    if (static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t' || c == '\r') allowed += c;
  return demos::html(allowed);
}

// A case as a Gradescope test's or a JUnit failure's text.
std::string case_text(const CaseResult& c) {
  std::string text = "law: " + c.law + "\n";
  if (!c.expected.empty()) text += "expected: " + c.expected + "\n";
  text += "measured: " + c.measured + "\n";
  if (!c.failure.empty()) text += "report: " + c.failure + "\n";
  if (!c.passed && !c.hint.empty()) text += "hint: " + c.hint + "\n";
  return text;
}

}  // namespace

std::string class_table(const std::string& folder, const std::vector<StudentResult>& results) {
  size_t width = 7;
  int compiled = 0, perfect = 0;
  for (const StudentResult& result : results) {
    width = std::max(width, result.student.size());
    compiled += result.compiled;
    perfect += result.compiled && result.passed() == result.max_score();
  }
  std::ostringstream table;
  table << "impulse grade " << folder << ": " << results.size() << " submissions, " << compiled << " compile, " << perfect
        << " pass every case\n\n";
  table << "  " << "student" << std::string(width - 7, ' ') << "  score  cases failed\n";
  for (const StudentResult& result : results) {
    const std::string score = score_text(result);
    table << "  " << result.student << std::string(width - result.student.size(), ' ') << "  " << std::string(5 - std::min<size_t>(5, score.size()), ' ')
          << score << "  " << remark(result) << "\n";
  }
  return table.str();
}

std::string class_csv(const std::vector<StudentResult>& results) {
  std::ostringstream csv;
  csv << "student,file,score,max_score,compiled,failed_cases,message";
  for (const std::string& name : case_names()) csv << "," << csv_field(name);
  csv << "\n";
  for (const StudentResult& result : results) {
    csv << csv_field(result.student) << "," << csv_field(result.file) << "," << (result.compiled ? result.passed() : 0) << ","
        << result.max_score() << "," << (result.compiled ? 1 : 0) << "," << csv_field(joined(result.failed_cases(), ";")) << ","
        << csv_field(result.compiled ? "" : result.message);
    for (const std::string& name : case_names()) {
      const auto found = std::find_if(result.cases.begin(), result.cases.end(), [&](const CaseResult& c) { return c.name == name; });
      csv << "," << (found == result.cases.end() ? "" : found->passed ? "1" : "0");
    }
    csv << "\n";
  }
  return csv.str();
}

std::string gradescope_json(const StudentResult& result) {
  toml::array tests;
  for (const CaseResult& c : result.cases)
    tests.push_back(toml::table{{"name", c.name + ": " + c.title}, {"score", c.passed ? 1.0 : 0.0}, {"max_score", 1.0},
                                {"status", c.passed ? "passed" : "failed"}, {"output", case_text(c)}, {"visibility", "visible"}});
  std::string output;
  if (result.compiled)
    output = std::to_string(result.passed()) + " of " + std::to_string(result.max_score()) + " cases pass (impulse grade).";
  else
    output = result.file + " was not graded: " + result.message + (result.details.empty() ? "" : "\n\n" + result.details);
  const toml::table root{{"score", double(result.compiled ? result.passed() : 0)}, {"output", output},
                         {"visibility", "visible"},                              {"stdout_visibility", "hidden"},
                         {"tests", tests}};
  std::ostringstream json;
  json << toml::json_formatter{root} << "\n";
  return json.str();
}

std::string junit_xml(const std::string& folder, const std::vector<StudentResult>& results) {
  std::ostringstream xml;
  int tests = 0, failures = 0;
  for (const StudentResult& result : results) {
    tests += 1 + int(result.cases.size());
    failures += (result.compiled ? 0 : 1) + int(result.failed_cases().size());
  }
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"impulse grade " << xml_text(folder) << "\" tests=\"" << tests
      << "\" failures=\"" << failures << "\">\n";
  for (const StudentResult& result : results) {
    xml << "  <testsuite name=\"" << xml_text(result.student) << "\" tests=\"" << 1 + result.cases.size() << "\" failures=\""
        << (result.compiled ? 0 : 1) + result.failed_cases().size() << "\">\n";
    xml << "    <testcase classname=\"" << xml_text(result.student) << "\" name=\"compile\"";
    if (result.compiled)
      xml << "/>\n";
    else
      xml << ">\n      <failure message=\"" << xml_text(result.message) << "\">" << xml_text(result.details) << "</failure>\n    </testcase>\n";
    for (const CaseResult& c : result.cases) {
      xml << "    <testcase classname=\"" << xml_text(result.student) << "\" name=\"" << xml_text(c.name) << "\"";
      if (c.passed)
        xml << "/>\n";
      else
        xml << ">\n      <failure message=\"" << xml_text(c.failure.empty() ? c.measured : c.failure) << "\">" << xml_text(case_text(c))
            << "</failure>\n    </testcase>\n";
    }
    xml << "  </testsuite>\n";
  }
  xml << "</testsuites>\n";
  return xml.str();
}

}  // namespace impulse::workshop
