// impulse-respond boxes itself in before it loads a student's shared object, so that nothing of
// the student's (constructors included) runs outside the box. In this order:
//   1. rlimits: memory, CPU time, file size 0, open files, no processes, no core dump;
//   2. new user, network and IPC namespaces, where the kernel lets it (no network at all);
//   3. no new privileges, then Landlock: of the file system, reading the shared object only; no
//      TCP; no signals or abstract sockets out of the box (what the kernel's ABI has);
//   4. a seccomp filter: an allowlist of what computing and answering on the socket need; every
//      other call waits on a listener that the engine answers (syscall_watch.h), and a call of
//      another architecture's numbering kills the process.
// What each layer covers where the kernel lacks one: README.md here, "The sandbox".
#pragma once
#include "demos/response/respond_protocol.h"
#include "demos/response/unique_fd.h"

#include <string>

namespace impulse::workshop {

struct Sandbox {
  SandboxMessage message{};  // what the engine is told: status, Landlock's ABI, the namespaces
  UniqueFd listener;         // the seccomp filter's, to hand to the engine
};

// Enters the sandbox for loading `shared_object`. message.status is kReplyFailed, with the
// reason, when a layer that is not optional (the rlimits, seccomp) could not be set up.
Sandbox enter_sandbox(const std::string& shared_object);

}  // namespace impulse::workshop
