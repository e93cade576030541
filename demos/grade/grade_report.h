// The grade's results for people (a table, a hint under each failure) and for machines (JSON),
// and the videos of the cases that failed: the student's pane beside the reference's.
#pragma once
#include "demos/grade/grade.h"

#include <string>
#include <vector>

namespace impulse::workshop {

// "impulse grade FILE: 10 of 13 cases pass", then a row per case: its name, pass or FAIL, what the
// law expected and what was measured, and under a failure its hint (or the response's report).
std::string grade_table(const std::string& file, const std::vector<CaseResult>& results);

// {"file": ..., "passed": n, "failed": n, "cases": [{"name", "title", "law", "expected", "measured",
// "passed", "hint", "failure"}, ...]}
std::string grade_json(const std::string& file, const std::vector<CaseResult>& results);

// DIRECTORY/CASE.mp4 for each failed case (made if need be): the response's run beside the
// reference's, at 854x480. A case whose response crashed gets none (there is no run to show).
// Returns the videos written.
std::vector<std::string> write_failure_videos(const std::string& directory, const std::string& file,
                                              const physics::OutsideResponseMaker& response, const std::vector<CaseResult>& results,
                                              bool progress);

}  // namespace impulse::workshop
