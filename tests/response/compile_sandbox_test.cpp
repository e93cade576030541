// The layers under the scan (demos/response/landlock.h, compile_sandbox.h): a process under a
// Landlock ruleset reads and writes only what it allows, and the compiler, handed an #include
// of a file outside by a translation unit that never went through the scan, says "Permission
// denied" and shows nothing of the file. Skipped, with the reason, where the kernel has no Landlock.
#include "demos/response/compile_sandbox.h"
#include "demos/response/landlock.h"
#include "tests/support/response_files.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

namespace impulse::workshop {
namespace {

namespace fs = std::filesystem;

#define SKIP_WITHOUT_LANDLOCK() \
  if (landlock_abi() == 0) GTEST_SKIP() << "this kernel has no Landlock (or has it off): the scan alone stands before the compiler"

// In a child: open `path` for reading or writing under `ruleset`; the errno (0 when it opened).
int open_under(const LandlockRuleset& ruleset, const std::string& path, int flags) {
  const pid_t child = fork();
  if (child == 0) {
    if (ruleset.restrict_self() != 0) _exit(255);
    const int fd = open(path.c_str(), flags, 0644);
    _exit(fd >= 0 ? 0 : errno);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Landlock, AProcessReadsAndWritesOnlyWhatItsRulesetAllows) {
  SKIP_WITHOUT_LANDLOCK();
  const std::string allowed = test::scratch_file("allowed.txt", "yes"), other = test::scratch_file("other.txt", "no");
  const fs::path room = fs::path(allowed).parent_path() / "room";
  fs::create_directories(room);
  LandlockRuleset ruleset;
  ASSERT_TRUE(ruleset.allow_reading(allowed));
  ASSERT_TRUE(ruleset.allow_everything(room.string()));
  EXPECT_EQ(open_under(ruleset, allowed, O_RDONLY), 0);
  EXPECT_EQ(open_under(ruleset, allowed, O_WRONLY), EACCES);
  EXPECT_EQ(open_under(ruleset, other, O_RDONLY), EACCES);
  EXPECT_EQ(open_under(ruleset, "/etc/passwd", O_RDONLY), EACCES);
  EXPECT_EQ(open_under(ruleset, (room / "made.txt").string(), O_WRONLY | O_CREAT), 0);
  EXPECT_EQ(open_under(ruleset, (fs::path(allowed).parent_path() / "made.txt").string(), O_WRONLY | O_CREAT), EACCES);
  EXPECT_FALSE(fs::exists(fs::path(allowed).parent_path() / "made.txt"));
}

TEST(CompileSandbox, AnIncludePastTheScanIsRefusedAndNotShown) {
  SKIP_WITHOUT_LANDLOCK();
  const std::string secret = test::scratch_file("hidden_tests.txt", "the course's hidden answer is 42\n");
  const fs::path build = fs::path(secret).parent_path() / "build";
  fs::remove_all(build);
  fs::create_directories(build);
  std::ofstream(build / "unit.cpp") << "#include \"" << secret << "\"\n";
  CompileJob job;
  const char* cxx = std::getenv("CXX");
  job.argv = {cxx != nullptr && *cxx != '\0' ? cxx : "c++", "-fsyntax-only", (build / "unit.cpp").string()};
  job.build_directory = build.string();
  job.log_path = (build / "compiler.log").string();
  const tex::ChildOutcome outcome = run_compiler(job);
  ASSERT_TRUE(outcome.started) << outcome.error;
  EXPECT_NE(outcome.exit_code, 0);
  const std::string log = test::read(job.log_path);
  EXPECT_NE(log.find("Permission denied"), std::string::npos) << log;
  EXPECT_EQ(log.find("hidden answer"), std::string::npos) << log;
}

TEST(CompileSandbox, ItsToolchainIsTheCompilersOwnDirectories) {
  const char* cxx = std::getenv("CXX");
  const std::vector<std::string> paths = toolchain_paths(cxx != nullptr && *cxx != '\0' ? cxx : "c++");
  EXPECT_NE(std::find(paths.begin(), paths.end(), "/usr/include"), paths.end());
  for (const std::string& path : paths) {
    EXPECT_NE(path.rfind("/home", 0), 0u) << path;
    EXPECT_NE(path.rfind("/root", 0), 0u) << path;
    EXPECT_NE(path, "/");
  }
}

}  // namespace
}  // namespace impulse::workshop
