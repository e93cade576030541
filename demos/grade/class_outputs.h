// A class's grades for people (a table: student, score, cases failed) and for the systems courses
// grade with: CSV, Gradescope's results.json (one per student), JUnit XML (GitLab, Jenkins, GitHub).
#pragma once
#include "demos/grade/class_results.h"

#include <string>
#include <vector>

namespace impulse::workshop {

// "impulse grade FOLDER: 20 submissions, 18 compile, 9 pass every case", then a row per student:
// its name, score (cases passed of 13) and the cases it failed, or why it was not graded.
std::string class_table(const std::string& folder, const std::vector<StudentResult>& results);

// A header, then a row per student: student, file, score, max_score, compiled, failed_cases
// (separated by ';'), message, and a column per case (1 passed, 0 failed, empty not graded).
std::string class_csv(const std::vector<StudentResult>& results);

// Gradescope's results.json (its published autograder format): score, output, and a test per
// case (name, score, max_score, status, output with the law, expected, measured and the hint).
std::string gradescope_json(const StudentResult& result);

// <testsuites> with a <testsuite> per student: a test case per grade case, and "compile".
std::string junit_xml(const std::string& folder, const std::vector<StudentResult>& results);

}  // namespace impulse::workshop
