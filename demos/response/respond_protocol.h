// What the engine and its response process (impulse-respond, respond_main.cpp) say to each other
// over their socket: first the sandbox it is in, then one call's bodies and contact out, the
// bodies back. Fixed-size messages of plain data; both ends are built together from this file.
#pragma once
#include "impulse/workshop_abi.h"

#include <cstdint>

namespace impulse::workshop {

struct CallMessage {
  impulse_workshop_body c0, c1;
  impulse_workshop_contact contact;
};

// impulse-respond's first message, before it loads anything: the sandbox it has entered, with its
// seccomp filter's listener attached (SCM_RIGHTS) when status is kReplyDone; else why it could not.
struct SandboxMessage {
  int32_t status = 0;
  int32_t landlock_abi = 0;  // 0: no Landlock
  int32_t namespaces = 0;    // kUserNamespace | ...
  char message[512];         // on failure
};
inline constexpr int32_t kUserNamespace = 1, kNetworkNamespace = 2, kIpcNamespace = 4;

// After loading, and after each call: status 0 and the bodies, or a failure in words.
struct ReplyMessage {
  int32_t status = 0;  // kReplyDone, or kReplyFailed with `message`
  impulse_workshop_body c0, c1;
  char message[1024];
};
inline constexpr int32_t kReplyDone = 0;
inline constexpr int32_t kReplyFailed = 1;

// impulse-respond's file descriptor for its socket to the engine (stdin is /dev/null, and its
// standard output and error are a pipe the engine reads: a student's printf cannot garble replies).
inline constexpr int kSocketDescriptor = 3;

// Who did it, in a report: the function, or the loading of the shared object (a constructor, or
// a global variable's initialiser, runs then, before the first call).
inline constexpr const char* kCallerWords = "AddCollisionImpulse";
inline constexpr const char* kLoaderWords = "its loading (a constructor or a global's initialiser, before the first call)";

}  // namespace impulse::workshop
