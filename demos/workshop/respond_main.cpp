// impulse-respond SO SECONDS: the process a student's AddCollisionImpulse runs in, so that its
// crash, abort or endless loop ends this process and never the engine's. It loads the shared
// object, says whether that worked, then answers calls on its socket until the engine closes it.
// The engine times every call; an alarm of our own (SECONDS and one more per call) ends this
// process too if the engine is gone while the student's code loops.
#include "demos/workshop/respond_protocol.h"

#include <dlfcn.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace impulse::workshop;

namespace {

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
  const double seconds = std::atof(argv[2]);
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
