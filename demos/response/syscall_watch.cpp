#include "demos/response/syscall_watch.h"

#include "demos/response/syscall_words.h"

#include <fcntl.h>
#include <linux/seccomp.h>
#include <seccomp.h>
#include <sys/syscall.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <new>
#include <utility>

namespace impulse::workshop {

namespace {

const int kOpenAt = seccomp_syscall_resolve_name("openat");
const int kStatAt = seccomp_syscall_resolve_name("newfstatat");

// The kernel's size of a notification, which it wants zeroed before it writes one.
size_t request_size() {
  static const size_t size = [] {
    seccomp_notif_sizes sizes{};
    return syscall(SYS_seccomp, SECCOMP_GET_NOTIF_SIZES, 0, &sizes) == 0 ? size_t(sizes.seccomp_notif) : sizeof(seccomp_notif);
  }();
  return size;
}

}  // namespace

SyscallWatch::SyscallWatch(UniqueFd listener, pid_t child, std::string shared_object)
    : listener_(std::move(listener)), child_(child), shared_object_(std::move(shared_object)) {
  if (seccomp_notify_alloc(&request_, &response_) != 0) throw std::bad_alloc();
}

SyscallWatch::~SyscallWatch() {
  if (request_ != nullptr) seccomp_notify_free(request_, response_);
}

SyscallWatch::SyscallWatch(SyscallWatch&& other) noexcept
    : listener_(std::move(other.listener_)),
      child_(other.child_),
      shared_object_(std::move(other.shared_object_)),
      request_(std::exchange(other.request_, nullptr)),
      response_(std::exchange(other.response_, nullptr)) {}

SyscallWatch& SyscallWatch::operator=(SyscallWatch&& other) noexcept {
  std::swap(listener_, other.listener_);
  std::swap(child_, other.child_);
  std::swap(shared_object_, other.shared_object_);
  std::swap(request_, other.request_);
  std::swap(response_, other.response_);
  return *this;
}

// The child waits in the call, single-threaded (it may start no thread), so the text cannot change
// while it is read; its memory is read page by page up to the string's end.
std::string SyscallWatch::read_text(uint64_t address) const {
  std::string text;
  char chunk[256];
  while (address != 0 && text.size() < 4096) {
    const size_t to_page_end = 4096 - (address % 4096);
    iovec local{chunk, std::min(sizeof chunk, to_page_end)}, remote{reinterpret_cast<void*>(address), local.iov_len};
    const ssize_t got = process_vm_readv(child_, &local, 1, &remote, 1, 0);
    if (got <= 0) break;
    const size_t length = strnlen(chunk, size_t(got));
    text.append(chunk, length);
    if (length < size_t(got)) break;
    address += uint64_t(got);
  }
  return text;
}

std::optional<std::string> SyscallWatch::answer() {
  std::memset(request_, 0, request_size());
  if (seccomp_notify_receive(listener_.get(), request_) != 0) return std::nullopt;  // the child is gone
  const seccomp_data& call = request_->data;
  uint64_t arguments[6];
  std::copy(std::begin(call.args), std::end(call.args), arguments);
  bool goes_on = false;
  if (call.nr == kOpenAt) {
    constexpr uint64_t kHarmless = O_CLOEXEC | O_LARGEFILE | O_NOCTTY | O_NONBLOCK;
    goes_on = (arguments[2] & ~kHarmless) == O_RDONLY && read_text(arguments[1]) == shared_object_;
  } else if (call.nr == kStatAt) {
    // fstat(fd): a descriptor of its own (not AT_FDCWD, which would look at the directory it runs in)
    goes_on = int32_t(arguments[0]) >= 0 && (arguments[3] & AT_EMPTY_PATH) != 0 && read_text(arguments[1]).empty();
  }
  std::string words;
  if (!goes_on) words = attempt_words(call.nr, arguments, [this](uint64_t address) { return read_text(address); });
  // The call is still the same process's (not a reused pid) when its id is still valid.
  const bool same_call = seccomp_notify_id_valid(listener_.get(), request_->id) == 0;
  std::memset(response_, 0, sizeof *response_);
  response_->id = request_->id;
  if (goes_on && same_call) {
    response_->flags = SECCOMP_USER_NOTIF_FLAG_CONTINUE;
  } else {
    response_->error = -EPERM;
  }
  seccomp_notify_respond(listener_.get(), response_);
  if (goes_on || !same_call) return std::nullopt;
  return words;
}

}  // namespace impulse::workshop
