// What the engine and its response process (impulse-respond, respond_main.cpp) say to each other
// over their socket: one call's bodies and contact out, the bodies back. Fixed-size messages of
// plain data; both ends are built together from this file.
#pragma once
#include "impulse/workshop_abi.h"

#include <cstdint>

namespace impulse::workshop {

struct CallMessage {
  impulse_workshop_body c0, c1;
  impulse_workshop_contact contact;
};

// After loading, and after each call: status 0 and the bodies, or a failure in words.
struct ReplyMessage {
  int32_t status = 0;  // kReplyDone, or kReplyFailed with `message`
  impulse_workshop_body c0, c1;
  char message[1024];
};
inline constexpr int32_t kReplyDone = 0;
inline constexpr int32_t kReplyFailed = 1;

// impulse-respond's file descriptor for its socket to the engine (stdin is /dev/null, and its
// standard output goes where its standard error does: a student's printf cannot garble replies).
inline constexpr int kSocketDescriptor = 3;

}  // namespace impulse::workshop
