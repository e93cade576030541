// The engine's end of a response process's seccomp filter (its listener): each system call the
// filter does not allow outright waits here until answered. Two kinds go on: the dynamic loader
// opening the shared object to read it, and fstat of a descriptor already open (glibc's fstat is
// newfstatat with an empty path). Every other is refused, and said in words.
#pragma once
#include "demos/response/unique_fd.h"

#include <sys/types.h>

#include <optional>
#include <string>

struct seccomp_notif;
struct seccomp_notif_resp;

namespace impulse::workshop {

class SyscallWatch {
 public:
  SyscallWatch() = default;
  SyscallWatch(UniqueFd listener, pid_t child, std::string shared_object);
  ~SyscallWatch();
  SyscallWatch(SyscallWatch&&) noexcept;
  SyscallWatch& operator=(SyscallWatch&&) noexcept;

  int fd() const { return listener_.get(); }  // readable when a call waits
  void close() { listener_.reset(); }

  // Answers the waiting call: nothing when it may go on (or the child is gone), else what it
  // tried ("open a file ('/etc/passwd')"), the call failed with EPERM.
  std::optional<std::string> answer();

 private:
  std::string read_text(uint64_t address) const;

  UniqueFd listener_;
  pid_t child_ = -1;
  std::string shared_object_;
  seccomp_notif* request_ = nullptr;
  seccomp_notif_resp* response_ = nullptr;
};

}  // namespace impulse::workshop
