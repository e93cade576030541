// A refused system call in a student's words (demos/response/syscall_words.h).
#include "demos/response/syscall_words.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <seccomp.h>

namespace impulse::workshop {
namespace {

std::string words(const char* call, uint64_t a0 = 0, uint64_t a1 = 0, uint64_t a2 = 0) {
  const uint64_t arguments[6] = {a0, a1, a2, 0, 0, 0};
  // The "addresses" are the texts' own, read back as the child's memory would be.
  return attempt_words(seccomp_syscall_resolve_name(call), arguments,
                       [](uint64_t address) { return address == 0 ? "" : std::string(reinterpret_cast<const char*>(address)); });
}

uint64_t address(const char* text) { return reinterpret_cast<uint64_t>(text); }

TEST(SyscallWords, OpeningSaysWhatAndWhich) {
  EXPECT_EQ(words("openat", uint64_t(AT_FDCWD), address("/etc/passwd"), O_RDONLY), "open a file ('/etc/passwd')");
  EXPECT_EQ(words("openat", uint64_t(AT_FDCWD), address("out.txt"), O_WRONLY | O_CREAT | O_TRUNC), "write a file ('out.txt')");
  EXPECT_EQ(words("openat", uint64_t(AT_FDCWD), address("/tmp"), O_RDONLY | O_DIRECTORY), "list a directory ('/tmp')");
  EXPECT_EQ(words("creat", address("new.txt")), "write a file ('new.txt')");
  EXPECT_EQ(words("unlinkat", uint64_t(AT_FDCWD), address("theirs.cpp")), "change a file ('theirs.cpp')");
  EXPECT_EQ(words("execve", address("/bin/sh")), "run a program ('/bin/sh')");
  EXPECT_EQ(words("newfstatat", uint64_t(AT_FDCWD), address("/root")), "look at a file ('/root')");
}

TEST(SyscallWords, ProcessesSocketsSignalsAndTheRest) {
  EXPECT_EQ(words("clone3"), "start a process (fork, system() or a thread)");
  EXPECT_EQ(words("socket"), "open a network socket");
  EXPECT_EQ(words("kill"), "send a signal to another process");
  EXPECT_EQ(words("ptrace"), "make the system call ptrace");
}

TEST(SyscallWords, APathIsQuotedPrintably) {
  EXPECT_EQ(quoted_path("a'b\n"), "'a\\x27b\\x0a'");
  EXPECT_EQ(quoted_path(std::string(300, 'x')), "'" + std::string(200, 'x') + "...'");
}

}  // namespace
}  // namespace impulse::workshop
