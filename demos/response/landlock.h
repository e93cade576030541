// Landlock (Linux 5.13 and later, unprivileged): a process restricts itself, and everything it
// starts, to the paths a ruleset allows. The ruleset handles every access the running kernel's
// ABI knows: files (reading, writing, creating, removing, truncating, device ioctls), TCP bind and
// connect (ABI 4), abstract UNIX sockets and signals out of the domain (ABI 6). What is handled
// and not allowed is refused (EACCES), whoever the process is, root included.
#pragma once
#include "demos/response/unique_fd.h"

#include <string>

namespace impulse::workshop {

// The kernel's Landlock ABI version, 0 where it has none or has it switched off.
int landlock_abi();

class LandlockRuleset {
 public:
  LandlockRuleset();  // inactive where the kernel has no Landlock

  bool active() const { return fd_.valid(); }
  int abi() const { return abi_; }

  // Beneath `path` (a directory, or one file): reading files, and listing directories unless it
  // is a file; running them too with `execute`. False if the path cannot be opened.
  bool allow_reading(const std::string& path, bool execute = false);
  // Beneath a directory: everything (reading, writing, making and removing files).
  bool allow_everything(const std::string& directory);
  // One file: reading and writing it (a device such as /dev/null).
  bool allow_reading_and_writing(const std::string& file);

  // In the calling process, from now on: no new privileges (what an unprivileged process needs
  // for Landlock and seccomp), then the ruleset. Only system calls: safe between fork and exec.
  // Returns 0, or the errno of the call that failed.
  int restrict_self() const;

 private:
  bool allow(const std::string& path, unsigned long long file_rights, unsigned long long directory_rights);

  int abi_ = 0;
  unsigned long long handled_ = 0;
  UniqueFd fd_;
};

}  // namespace impulse::workshop
