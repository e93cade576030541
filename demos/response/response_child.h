// A compiled response run in a child process (impulse-respond) boxed in by a sandbox
// (sandbox_child.h): the engine's OutsideResponse for a student's AddCollisionImpulse. Each call
// goes over a socket and is timed; a crash, an abort, an endless loop, a NaN, a system call
// graded code may not make, or printing past its limit ends the call with
// physics::ResponseFailure saying which, and the child is gone (every later call says the same).
// The child starts at the first call.
#pragma once
#include "demos/response/syscall_watch.h"
#include "demos/response/unique_fd.h"
#include "physics/outside_response.h"

#include <sys/types.h>

#include <string>

namespace impulse::workshop {

inline constexpr double kDefaultTimeLimit = 2;  // s per call, unless --time-limit says otherwise

class ChildResponse : public physics::OutsideResponse {
 public:
  // `label` names the response in messages (the student's file); `shared_object` is built.
  ChildResponse(std::string shared_object, std::string label, double time_limit = kDefaultTimeLimit);
  ~ChildResponse() override;  // ends the child
  ChildResponse(const ChildResponse&) = delete;
  ChildResponse& operator=(const ChildResponse&) = delete;

  void respond(physics::PlainBody& a, physics::PlainBody& b, const physics::PlainContact& contact) override;

  // Starts the child and loads the shared object, if not yet done. Throws ResponseFailure.
  void start();

  // Once started: the sandbox it runs in, in words ("seccomp allowlist; Landlock ABI 7; ...").
  const std::string& sandbox() const { return sandbox_; }

 private:
  void receive_sandbox();
  void receive(void* data, size_t size, bool loading);
  bool copy_output(bool loading);  // false when the child's output is closed
  [[noreturn]] void failed(const std::string& why);
  std::string ended_how(bool loading);
  void stop();

  std::string shared_object_, label_;
  double time_limit_;
  pid_t pid_ = -1;
  UniqueFd socket_, output_;  // the calls; what the child prints
  SyscallWatch watch_;        // the calls its filter sends to us
  long printed_ = 0;          // bytes of output so far
  std::string sandbox_;
  std::string failure_;  // once failed, why: every later call says the same
};

// Where impulse-respond is: $IMPULSE_RESPOND, else beside the running program, else the build's.
std::string responder_path();

// A maker for the world's settings: each world gets its own child.
physics::OutsideResponseMaker child_response_maker(const std::string& shared_object, const std::string& label,
                                                   double time_limit = kDefaultTimeLimit);

}  // namespace impulse::workshop
