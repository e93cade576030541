// The command line itself: options after the subcommand; every command's --help with examples and
// exit codes.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

TEST(Cli, OptionsWorkAfterTheSubcommandAndHelpShowsExamplesAndExitCodes) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  EXPECT_TRUE(run_in_process({"check", (dir / "slide.toml").string(), "-q"}).succeeded());
  for (const char* command : {"render", "compare", "simulate", "check", "verify", "catalogue", "gallery"}) {
    const testing::ProgramRun help = run_in_process({command, "--help"});
    EXPECT_TRUE(help.succeeded()) << command;
    EXPECT_NE(help.stdout_text.find("Examples:\n  impulse " + std::string(command)), std::string::npos) << help.stdout_text;
    EXPECT_NE(help.stdout_text.find("Exit codes: 0 "), std::string::npos) << help.stdout_text;
  }
  const testing::ProgramRun none = run_in_process({});
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.stderr_text.find("A subcommand is required"), std::string::npos) << none.stderr_text;
  const testing::ProgramRun unknown = run_in_process({"frobnicate"});
  EXPECT_EQ(unknown.exit_code, 1) << unknown.describe();
}

}  // namespace
}  // namespace impulse
