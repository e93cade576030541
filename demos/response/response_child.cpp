#include "demos/response/response_child.h"

#include "demos/response/respond_protocol.h"
#include "demos/response/sandbox_limits.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

namespace fs = std::filesystem;

namespace impulse::workshop {

namespace {

constexpr double kLoadSeconds = 3;  // to start the process, box it in and load the shared object, over the call's limit

void put(impulse_workshop_body& out, const physics::PlainBody& in) {
  std::copy(in.centre.begin(), in.centre.end(), out.centre);
  out.inv_mass = in.inv_mass;
  std::copy(in.lin_velocity.begin(), in.lin_velocity.end(), out.lin_velocity);
  std::copy(in.forces.begin(), in.forces.end(), out.forces);
  std::copy(in.inv_inertia.begin(), in.inv_inertia.end(), out.inv_inertia);
  std::copy(in.ang_velocity.begin(), in.ang_velocity.end(), out.ang_velocity);
  std::copy(in.orientation.begin(), in.orientation.end(), out.orientation);
  std::copy(in.torques.begin(), in.torques.end(), out.torques);
  std::copy(in.world_inv_inertia.begin(), in.world_inv_inertia.end(), out.world_inv_inertia);
  out.restitution = in.restitution;
  out.friction = in.friction;
}

void get(physics::PlainBody& out, const impulse_workshop_body& in) {
  std::copy(in.lin_velocity, in.lin_velocity + 3, out.lin_velocity.begin());
  std::copy(in.ang_velocity, in.ang_velocity + 3, out.ang_velocity.begin());
}

std::string signal_meaning(int signal) {
  switch (signal) {
    case SIGSEGV: return "crashed (SIGSEGV, a segmentation fault: it touched memory it may not, a bad pointer or index?)";
    case SIGBUS: return "crashed (SIGBUS, a bad memory access)";
    case SIGFPE: return "crashed (SIGFPE, an arithmetic error: an integer divided by zero?)";
    case SIGILL: return "crashed (SIGILL, an illegal instruction: a function that returns nothing where it should?)";
    case SIGABRT: return "aborted (SIGABRT: an assert failed, or abort() was called; its message is above)";
    case SIGALRM: return "did not return in time and was stopped (SIGALRM)";
    case SIGKILL: return "was killed (SIGKILL: out of memory?)";
    case SIGXCPU:
      return "used more than " + std::to_string(limits::kCpuSeconds) + " s of processor time (SIGXCPU), which graded code may not";
    case SIGSYS: return "made a system call of another architecture's numbering (SIGSYS), which graded code may not do";
  }
  return std::string("was ended by signal ") + std::to_string(signal) + " (" + strsignal(signal) + ")";
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

}  // namespace

std::string responder_path() {
  if (const char* own = std::getenv("IMPULSE_RESPOND"); own != nullptr && *own != '\0') return own;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (!error && fs::exists(self.parent_path() / "impulse-respond")) return (self.parent_path() / "impulse-respond").string();
  return IMPULSE_RESPONDER;
}

ChildResponse::ChildResponse(std::string shared_object, std::string label, double time_limit)
    : shared_object_(std::move(shared_object)), label_(std::move(label)), time_limit_(time_limit) {}

ChildResponse::~ChildResponse() { stop(); }

void ChildResponse::stop() {
  socket_.reset();
  watch_.close();
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  pid_ = -1;
  output_.reset();
}

void ChildResponse::failed(const std::string& why) {
  failure_ = label_ + ": " + why;
  stop();
  throw physics::ResponseFailure(failure_);
}

// After the socket closed: how the child ended, and the last of what it printed.
std::string ChildResponse::ended_how(bool loading) {
  int status = 0;
  pid_t done;
  while ((done = waitpid(pid_, &status, 0)) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  while (output_.valid() && copy_output(loading)) {
  }
  if (done < 0) return "ended (how is not known)";
  if (WIFSIGNALED(status)) return signal_meaning(WTERMSIG(status));
  return "ended its process with exit code " + std::to_string(WEXITSTATUS(status)) + " (exit() in the code, or a sanitizer's report above?)";
}

// What the child printed, copied to our standard error up to a limit; printing past its limit
// stops it. Returns false when there is nothing more to read now (or ever).
bool ChildResponse::copy_output(bool loading) {
  char chunk[16384];
  const ssize_t got = read(output_.get(), chunk, sizeof chunk);
  if (got == 0) output_.reset();
  if (got <= 0) return false;
  const long shown = std::clamp(limits::kShownOutputBytes - printed_, 0L, long(got));
  std::fwrite(chunk, 1, size_t(shown), stderr);
  printed_ += got;
  if (shown < got && printed_ - got <= limits::kShownOutputBytes)
    std::fprintf(stderr, "\nimpulse: %s printed more; the rest is not shown\n", label_.c_str());
  if (printed_ > limits::kOutputBytes && pid_ > 0)
    failed(std::string(loading ? kLoaderWords : kCallerWords) + " printed more than " + limits::size_words(limits::kOutputBytes) +
           " (a print in a loop?), which graded code may not do");
  return true;
}

void ChildResponse::receive(void* data, size_t size, bool loading) {
  const double limit = loading ? time_limit_ + kLoadSeconds : time_limit_;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit);
  const std::string who = loading ? kLoaderWords : kCallerWords;
  char* bytes = static_cast<char*>(data);
  while (size > 0) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    pollfd waiting[3] = {{socket_.get(), POLLIN, 0}, {output_.get(), POLLIN, 0}, {watch_.fd(), POLLIN, 0}};
    const int ready = left > 0 ? poll(waiting, 3, int(std::ceil(left * 1000))) : 0;
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0)
      failed(loading ? who + " did not end within " + seconds_text(limit) + ": an endless loop?"
                     : who + " did not return within " + seconds_text(limit) + ": an endless loop? (the limit is --time-limit's)");
    if (waiting[2].revents & POLLIN) {
      if (const std::optional<std::string> attempt = watch_.answer())
        failed(who + " tried to " + *attempt + ", which graded code may not do");
    } else if (waiting[2].revents != 0) {
      watch_.close();  // no process left to watch
    }
    if (waiting[1].revents != 0) copy_output(loading);
    if (waiting[0].revents == 0) continue;
    const ssize_t got = recv(socket_.get(), bytes, size, 0);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) failed((loading ? "loading it: the process " : "AddCollisionImpulse ") + ended_how(loading));
    bytes += got;
    size -= size_t(got);
  }
}

// The child's first message: the sandbox it entered, and its seccomp listener.
void ChildResponse::receive_sandbox() {
  SandboxMessage message{};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
  iovec data{&message, sizeof message};
  msghdr header{};
  header.msg_iov = &data;
  header.msg_iovlen = 1;
  header.msg_control = control;
  header.msg_controllen = sizeof control;
  pollfd waiting{socket_.get(), POLLIN, 0};
  if (poll(&waiting, 1, int(kLoadSeconds * 1000)) <= 0) failed("its sandbox was not set up within " + seconds_text(kLoadSeconds));
  ssize_t got;
  while ((got = recvmsg(socket_.get(), &header, MSG_CMSG_CLOEXEC)) < 0 && errno == EINTR) {
  }
  if (got <= 0) failed("its sandbox: the process " + ended_how(true));
  UniqueFd listener;
  for (cmsghdr* part = CMSG_FIRSTHDR(&header); part != nullptr; part = CMSG_NXTHDR(&header, part))
    if (part->cmsg_level == SOL_SOCKET && part->cmsg_type == SCM_RIGHTS) {
      int fd;
      std::memcpy(&fd, CMSG_DATA(part), sizeof fd);
      listener.reset(fd);
    }
  if (got < ssize_t(sizeof message)) {
    auto rest = reinterpret_cast<char*>(&message) + got;
    receive(rest, sizeof message - size_t(got), true);
  }
  if (message.status != kReplyDone || !listener.valid())
    failed("impulse cannot box it in on this machine, so it does not run it: " +
           std::string(message.message, strnlen(message.message, sizeof message.message)));
  watch_ = SyscallWatch(std::move(listener), pid_, shared_object_);
  sandbox_ = "a seccomp allowlist (any other system call refused and reported)";
  sandbox_ += message.landlock_abi > 0 ? "; Landlock ABI " + std::to_string(message.landlock_abi) + " (it reads its shared object, nothing else)"
                                       : "; no Landlock (the kernel has none)";
  const int namespaces = message.namespaces;
  if (namespaces & kNetworkNamespace)
    sandbox_ += std::string("; ") + (namespaces & kUserNamespace ? "user, " : "") + "network and IPC namespaces of its own";
  sandbox_ += "; at most " + limits::size_words(limits::kMemoryBytes) + " of memory, " + std::to_string(limits::kCpuSeconds) +
              " s of processor time, " + std::to_string(limits::kOpenFiles) + " open files, no file written, no process started";
}

void ChildResponse::start() {
  if (!failure_.empty()) throw physics::ResponseFailure(failure_);
  if (pid_ > 0) return;
  int pair[2], pipe_ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
    failed(std::string("cannot make a socket for it: ") + std::strerror(errno));
  socket_.reset(pair[0]);
  UniqueFd socket_end(pair[1]);
  if (pipe2(pipe_ends, O_CLOEXEC) != 0) failed(std::string("cannot make a pipe for its output: ") + std::strerror(errno));
  output_.reset(pipe_ends[0]);
  UniqueFd output_end(pipe_ends[1]);
  fcntl(output_.get(), F_SETFL, O_NONBLOCK);
  // Never 0 to 3 themselves: dup2 onto those must clear close-on-exec.
  const UniqueFd child_socket(fcntl(socket_end.get(), F_DUPFD_CLOEXEC, 10)), child_output(fcntl(output_end.get(), F_DUPFD_CLOEXEC, 10));
  socket_end.reset();
  output_end.reset();

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, child_output.get(), 1);
  posix_spawn_file_actions_adddup2(&actions, child_output.get(), 2);
  posix_spawn_file_actions_adddup2(&actions, child_socket.get(), kSocketDescriptor);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group: a Ctrl-C meant for impulse does not reach it (impulse ends it).
  sigset_t defaults, none;
  sigemptyset(&defaults);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGALRM, SIGXFSZ}) sigaddset(&defaults, signal);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  const std::string program = responder_path(), seconds = std::to_string(time_limit_);
  std::vector<char*> argv = {const_cast<char*>(program.c_str()), const_cast<char*>(shared_object_.c_str()),
                             const_cast<char*>(seconds.c_str()), nullptr};
  // None of the grader's environment (tokens, paths) for the student's code to read; only what
  // the dynamic loader may need to find the C++ library of $CXX.
  std::string library_path = "LD_LIBRARY_PATH=";
  if (const char* own = std::getenv("LD_LIBRARY_PATH")) library_path += own;
  std::vector<char*> environment = {library_path.data(), nullptr};
  const int error = posix_spawn(&pid_, program.c_str(), &actions, &attributes, argv.data(), environment.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0) {
    pid_ = -1;
    failed("cannot start " + program + ": " + std::strerror(error));
  }
  receive_sandbox();
  ReplyMessage hello;
  receive(&hello, sizeof hello, true);
  if (hello.status != kReplyDone) failed(std::string(hello.message, strnlen(hello.message, sizeof hello.message)));
}

void ChildResponse::respond(physics::PlainBody& a, physics::PlainBody& b, const physics::PlainContact& contact) {
  start();
  CallMessage call{};
  put(call.c0, a);
  put(call.c1, b);
  std::copy(contact.point.begin(), contact.point.end(), call.contact.point);
  std::copy(contact.normal.begin(), contact.normal.end(), call.contact.normal);
  call.contact.penetration = contact.penetration;
  call.contact.time_step = contact.time_step;
  const char* bytes = reinterpret_cast<const char*>(&call);
  for (size_t size = sizeof call; size > 0;) {
    const ssize_t sent = send(socket_.get(), bytes, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) failed("AddCollisionImpulse " + ended_how(false));
    bytes += sent;
    size -= size_t(sent);
  }
  ReplyMessage reply;
  receive(&reply, sizeof reply, false);
  if (reply.status != kReplyDone) failed(std::string(reply.message, strnlen(reply.message, sizeof reply.message)));
  get(a, reply.c0);
  get(b, reply.c1);
}

physics::OutsideResponseMaker child_response_maker(const std::string& shared_object, const std::string& label, double time_limit) {
  return [=] { return std::make_unique<ChildResponse>(shared_object, label, time_limit); };
}

}  // namespace impulse::workshop
