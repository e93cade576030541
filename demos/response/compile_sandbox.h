// The compiler run on a student's file with limits and, where the kernel has Landlock, seeing
// only what a build needs: the compiler's own directories and the system's headers and libraries
// (read, and run), impulse's header, the student's file, /dev/null, and a build directory of its
// own (everything: the translation unit, temporaries, the shared object). Another submission, a
// course's hidden data, the grader's home: refused (EACCES), so an #include of them that got past
// include_check.h shows a "Permission denied", never a line of theirs. Each of the compiler's
// processes has the rlimits of sandbox_limits.h (memory, CPU time, the size of every file it
// writes, its messages' included); the whole compile has a time limit on the clock.
#pragma once
#include "tex/child_run.h"

#include <string>
#include <vector>

namespace impulse::workshop {

struct CompileJob {
  std::vector<std::string> argv;   // the compiler and its arguments
  std::string build_directory;     // its own: it writes here and nowhere else (TMPDIR too)
  std::string log_path;            // its messages, in build_directory
  std::vector<std::string> readable;  // besides the toolchain's: impulse's include directory, the student's file
  std::string toolchain_list;         // where the toolchain's paths are kept between processes (empty: not kept)
};

tex::ChildOutcome run_compiler(const CompileJob& job);

// The toolchain's directories, as the compiler names them (-print-search-dirs, its #include
// search list) with /usr/bin, /bin, /lib64 and /etc/ld.so.cache: what it may read and run. Asking
// takes two runs of the compiler (a quarter of a second): the answer is kept for the process, and
// in `list` when given (a line a path; a class grades each file in a process of its own).
std::vector<std::string> toolchain_paths(const std::string& compiler, const std::string& list = "");

}  // namespace impulse::workshop
