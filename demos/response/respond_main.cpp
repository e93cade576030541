// impulse-respond SO SECONDS: the process a student's AddCollisionImpulse runs in, so that its
// crash, abort or endless loop ends this process and never the engine's, and what it tries
// beyond computing is refused. It boxes itself in (sandbox_child.h) and hands the engine its
// seccomp listener, then loads the shared object, says whether that worked, and answers calls on
// its socket until the engine closes it. The engine times every call; an alarm of our own
// (SECONDS and one more per call) ends this process too if the engine is gone while the student's
// code loops, and the CPU rlimit if the code blocks the alarm.
#include "demos/response/respond_protocol.h"
#include "demos/response/sandbox_child.h"

#include <dlfcn.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

using namespace impulse::workshop;

namespace {

bool loading = true;  // the shared object's constructors may be running

bool receive_all(void* data, size_t size) {
  char* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = recv(kSocketDescriptor, bytes, size, 0);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    bytes += got;
    size -= size_t(got);
  }
  return true;
}

void send_reply(const ReplyMessage& reply) {
  const char* bytes = reinterpret_cast<const char*>(&reply);
  size_t size = sizeof reply;
  while (size > 0) {
    const ssize_t sent = send(kSocketDescriptor, bytes, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) std::exit(0);  // the engine is gone
    bytes += sent;
    size -= size_t(sent);
  }
}

void fail(ReplyMessage& reply, const std::string& text) {
  reply.status = kReplyFailed;
  std::snprintf(reply.message, sizeof reply.message, "%s", text.c_str());
}

void set_alarm(double seconds) {
  itimerval timer{};
  timer.it_value.tv_sec = time_t(seconds);
  timer.it_value.tv_usec = suseconds_t((seconds - std::floor(seconds)) * 1e6);
  setitimer(ITIMER_REAL, &timer, nullptr);
}

// Its listener to the engine, before anything of the student's runs; or why there is none.
void send_sandbox(const Sandbox& sandbox) {
  iovec data{const_cast<SandboxMessage*>(&sandbox.message), sizeof sandbox.message};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  msghdr message{};
  message.msg_iov = &data;
  message.msg_iovlen = 1;
  if (sandbox.listener.valid()) {
    message.msg_control = control;
    message.msg_controllen = sizeof control;
    cmsghdr* header = CMSG_FIRSTHDR(&message);
    header->cmsg_level = SOL_SOCKET;
    header->cmsg_type = SCM_RIGHTS;
    header->cmsg_len = CMSG_LEN(sizeof(int));
    const int fd = sandbox.listener.get();
    std::memcpy(CMSG_DATA(header), &fd, sizeof fd);
  }
  while (sendmsg(kSocketDescriptor, &message, MSG_NOSIGNAL) < 0)
    if (errno != EINTR) std::exit(1);
}

// operator new found no memory under the limit: said as such, rather than as std::bad_alloc or
// the abort of a constructor that threw it. Without allocating.
void out_of_memory() {
  ReplyMessage reply{};
  reply.status = kReplyFailed;
  rlimit memory{};
  getrlimit(RLIMIT_AS, &memory);
  std::snprintf(reply.message, sizeof reply.message, "%s used more memory than graded code may (its limit is %llu MiB)",
                loading ? kLoaderWords : kCallerWords, static_cast<unsigned long long>(memory.rlim_cur >> 20));
  send_reply(reply);
  _exit(3);
}

// Nothing of impulse's but the socket and the standard streams.
void close_other_descriptors() {
  if (close_range(kSocketDescriptor + 1, ~0U, 0) == 0) return;
  for (int fd = kSocketDescriptor + 1; fd < 1024; ++fd) close(fd);  // before Linux 5.9
}

bool finite(const impulse_workshop_body& body) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(body.lin_velocity[i]) || !std::isfinite(body.ang_velocity[i])) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "impulse-respond SO SECONDS: started by impulse, not by hand\n");
    return 1;
  }
  close_other_descriptors();
  const double seconds = std::atof(argv[2]);
  {
    Sandbox sandbox = enter_sandbox(argv[1]);
    send_sandbox(sandbox);
    if (sandbox.message.status != kReplyDone) return 1;
  }
  std::set_new_handler(out_of_memory);
  ReplyMessage reply{};
  set_alarm(seconds + 1);  // a constructor of the student's may loop too
  void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  impulse_workshop_respond_function respond = nullptr;
  if (library == nullptr) {
    fail(reply, std::string("cannot load it: ") + dlerror());
  } else {
    auto version = reinterpret_cast<int (*)()>(dlsym(library, IMPULSE_WORKSHOP_VERSION_SYMBOL));
    respond = reinterpret_cast<impulse_workshop_respond_function>(dlsym(library, IMPULSE_WORKSHOP_ENTRY));
    if (version == nullptr || respond == nullptr)
      fail(reply, "it is not a response built by impulse (no " IMPULSE_WORKSHOP_ENTRY "): build it with `impulse response FILE.cpp -o FILE.so`");
    else if (version() != IMPULSE_WORKSHOP_ABI_VERSION)
      fail(reply, "it was built for another version of impulse: build it again with `impulse response FILE.cpp -o FILE.so`");
  }
  set_alarm(0);
  loading = false;
  send_reply(reply);
  if (reply.status != kReplyDone) return 1;

  for (CallMessage call; receive_all(&call, sizeof call);) {
    reply = ReplyMessage{};
    reply.c0 = call.c0;
    reply.c1 = call.c1;
    set_alarm(seconds + 1);
    if (respond(&reply.c0, &reply.c1, &call.contact, reply.message, int(sizeof reply.message)) != 0)
      reply.status = kReplyFailed;
    set_alarm(0);
    if (reply.status == kReplyDone && (!finite(reply.c0) || !finite(reply.c1)))
      fail(reply, "it made a velocity that is not a number (NaN or infinite): a division by zero? (DBG_CHECKVECTOR says where)");
    send_reply(reply);
  }
  return 0;
}
