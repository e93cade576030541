#include "demos/grade/class_grade.h"

#include "demos/child_jobs.h"
#include "demos/response/response_build.h"
#include "tex/tex_cache.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace impulse::workshop {

namespace {

bool is_source(const fs::directory_entry& entry) { return entry.path().extension() == ".cpp"; }

// The last lines of a child's log: what it said before it failed to write its report.
std::string tail_of(const fs::path& log) {
  std::ifstream file(log);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  return text.size() > 2000 ? text.substr(text.size() - 2000) : text;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// What a result was graded from: the submission's text, this program (its own bytes: another build
// may judge otherwise) and the time limit. Empty when the file cannot be read.
std::string graded_from(const Submission& submission, double time_limit) {
  static const std::string program = tex::text_hash(read_bytes("/proc/self/exe"));
  std::ifstream file(submission.file, std::ios::binary);
  if (!file) return "";
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  return tex::text_hash(program + "\n" + std::to_string(time_limit) + "\n" + text);
}

}  // namespace

std::string kept_results_directory() { return cache_directory() + "/grades"; }

std::vector<Submission> find_submissions(const std::string& folder) {
  if (!fs::is_directory(folder)) throw std::invalid_argument(folder + ": no such folder");
  std::vector<Submission> found;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(".")) continue;
    if (entry.is_symlink()) {
      if (is_source(entry) || fs::is_directory(entry.path()))
        found.push_back({entry.path().stem().string(), entry.path().string(), "a symbolic link, which is never followed"});
      continue;
    }
    if (entry.is_regular_file() && is_source(entry)) {
      found.push_back({entry.path().stem().string(), entry.path().string(), ""});
    } else if (entry.is_directory()) {
      std::vector<std::string> sources;
      for (const fs::directory_entry& inner : fs::directory_iterator(entry.path()))
        if (is_source(inner) && (inner.is_regular_file() || inner.is_symlink())) sources.push_back(inner.path().string());
      std::sort(sources.begin(), sources.end());
      if (sources.size() == 1)
        found.push_back({name, sources.front(), ""});
      else
        found.push_back({name, entry.path().string(),
                         sources.empty() ? "no .cpp file in the folder" : "several .cpp files in the folder: one is graded, which?"});
    }
  }
  std::sort(found.begin(), found.end(), [](const Submission& a, const Submission& b) { return a.student < b.student; });
  return found;
}

std::vector<StudentResult> grade_class(const std::vector<Submission>& submissions, const ClassRun& run) {
  std::vector<StudentResult> results;
  std::vector<size_t> graded;  // the submissions given a process, by their result's index
  std::vector<std::string> keys;  // what each was graded from (graded_from), by job
  std::vector<std::vector<std::string>> jobs;
  size_t unchanged = 0;
  if (!run.kept.empty()) {
    std::error_code made;
    fs::create_directories(run.kept, made);
  }
  const fs::path reports = fs::temp_directory_path() / ("impulse-grade-" + std::to_string(getpid()));
  fs::create_directories(reports);
  for (size_t i = 0; i < submissions.size(); ++i) {
    if (int(i % size_t(run.shards)) != run.shard - 1) continue;
    const Submission& submission = submissions[i];
    StudentResult result;
    result.student = submission.student;
    result.file = submission.file;
    result.message = submission.problem;
    if (submission.problem.empty()) {
      const std::string key = run.kept.empty() ? "" : graded_from(submission, run.time_limit);
      std::optional<StudentResult> earlier;
      if (!key.empty()) earlier = read_student_report((fs::path(run.kept) / (key + ".toml")).string());
      if (earlier) {
        earlier->student = result.student;
        earlier->file = result.file;
        result = *earlier;
        ++unchanged;
        if (!run.reports.empty()) {
          fs::create_directories(run.reports);
          write_student_report((fs::path(run.reports) / (result.student + ".toml")).string(), result);
        }
      } else {
        graded.push_back(results.size());
        keys.push_back(key);
        const std::string report = (reports / (std::to_string(jobs.size()) + ".toml")).string();
        jobs.push_back({"grade", submission.file, "--time-limit", std::to_string(run.time_limit), "--class-report", report});
      }
    }
    results.push_back(result);
  }
  if (run.progress && unchanged > 0)
    std::fprintf(stderr, "%zu unchanged since they were graded: their results kept (--regrade grades them again)\n", unchanged);
  if (!run.reports.empty()) fs::create_directories(run.reports);
  const auto began = std::chrono::steady_clock::now();
  size_t finished = 0;
  demos::run_child_jobs(
      jobs, run.jobs, [](size_t) {},
      [&](size_t job, int code) {
        StudentResult& result = results[graded[job]];
        const std::string report = (reports / (std::to_string(job) + ".toml")).string();
        if (std::optional<StudentResult> read = read_student_report(report)) {
          read->student = result.student;
          result = *read;
          if (!run.reports.empty()) write_student_report((fs::path(run.reports) / (result.student + ".toml")).string(), result);
          if (!keys[job].empty()) try {  // kept for a re-run; one that cannot be kept is graded again then
              write_student_report((fs::path(run.kept) / (keys[job] + ".toml")).string(), result);
            } catch (const std::exception&) {
            }
        } else {
          result.message = "impulse could not grade it (exit code " + std::to_string(code) + ")";
          result.details = tail_of(report + ".log");
        }
        if (run.progress)
          std::fprintf(stderr, "[%zu/%zu] %s: %s (%.0f s so far)\n", ++finished, jobs.size(), result.student.c_str(),
                       result.compiled ? (std::to_string(result.passed()) + " of " + std::to_string(result.max_score()) + " cases").c_str()
                                       : result.message.c_str(),
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count());
      });
  std::error_code error;
  fs::remove_all(reports, error);
  return results;
}

std::vector<StudentResult> merge_class(const std::vector<Submission>& submissions, const std::string& reports) {
  std::vector<StudentResult> results;
  for (const Submission& submission : submissions) {
    StudentResult result;
    result.student = submission.student;
    result.file = submission.file;
    result.message = submission.problem;
    if (submission.problem.empty()) {
      if (std::optional<StudentResult> read = read_student_report((fs::path(reports) / (submission.student + ".toml")).string()))
        result = *read;
      else
        result.message = "not graded: no report in " + reports + " (did its shard run?)";
    }
    results.push_back(result);
  }
  return results;
}

}  // namespace impulse::workshop
