// A class's folder graded in one command (`impulse grade FOLDER --jobs N`): each submission in a
// process of its own (`impulse grade FILE --class-report REPORT`, its own sandbox, its output kept
// out of the class's), N at a time, and their results gathered.
#pragma once
#include "demos/grade/class_results.h"

#include <string>
#include <vector>

namespace impulse::workshop {

// One student's: every *.cpp of the folder (the student is its name without .cpp), or the one
// .cpp of each of its folders (the student is the folder's name). `problem` says why one cannot
// be graded (a link, a folder without a .cpp or with several).
struct Submission {
  std::string student, file;
  std::string problem;
};

// The folder's submissions, by student name. Throws std::invalid_argument if it is not a folder.
std::vector<Submission> find_submissions(const std::string& folder);

struct ClassRun {
  int jobs = 1;
  double time_limit = 2;
  int shard = 1, shards = 1;  // every Nth submission in name order, from the Kth
  bool progress = true;       // a line on stderr as each submission ends
  std::string reports;        // when set, each graded student's report is kept here, as STUDENT.toml
  // When set, each result is also kept here by what it was graded from (the file's text, this
  // program, the time limit), and a submission graded so before is not graded again: a re-run
  // grades only what changed.
  std::string kept;
};

// The folder where `impulse grade FOLDER` keeps its results (ClassRun::kept): beside the
// compiled responses' cache (response_build.h).
std::string kept_results_directory();

// Grades each submission in a child process of this program; the results in name order.
std::vector<StudentResult> grade_class(const std::vector<Submission>& submissions, const ClassRun& run);

// The results that shards kept in `reports` (ClassRun::reports), for every submission, as if one
// run had graded them all: a submission with no report there is a row that says so.
std::vector<StudentResult> merge_class(const std::vector<Submission>& submissions, const std::string& reports);

}  // namespace impulse::workshop
