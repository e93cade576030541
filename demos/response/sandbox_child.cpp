#include "demos/response/sandbox_child.h"

#include "demos/response/landlock.h"
#include "demos/response/sandbox_limits.h"

#include <sched.h>
#include <seccomp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace impulse::workshop {

namespace {

bool limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit value{soft, hard};
  return setrlimit(resource, &value) == 0;
}

bool set_limits() {
  return limit(RLIMIT_AS, limits::kMemoryBytes, limits::kMemoryBytes) &&
         limit(RLIMIT_CPU, limits::kCpuSeconds, limits::kCpuSeconds + 1) &&  // SIGXCPU, then SIGKILL
         limit(RLIMIT_FSIZE, 0, 0) && limit(RLIMIT_NOFILE, limits::kOpenFiles, limits::kOpenFiles) &&
         limit(RLIMIT_NPROC, 0, 0) && limit(RLIMIT_CORE, 0, 0) && limit(RLIMIT_MEMLOCK, 0, 0) &&
         limit(RLIMIT_MSGQUEUE, 0, 0);
}

// As many of user, network and IPC namespaces as the kernel allows: with a user namespace an
// unprivileged process may have the others, and root loses its capabilities over the machine's
// files (only the permission bits are left).
int enter_namespaces() {
  if (unshare(CLONE_NEWUSER | CLONE_NEWNET | CLONE_NEWIPC) == 0) return kUserNamespace | kNetworkNamespace | kIpcNamespace;
  if (unshare(CLONE_NEWNET | CLONE_NEWIPC) == 0) return kNetworkNamespace | kIpcNamespace;  // root, without user namespaces
  return 0;
}

using Filter = std::unique_ptr<void, decltype(&seccomp_release)>;

// Argument `index` equals `value` (libseccomp's SCMP_A0 is a C compound literal).
scmp_arg_cmp argument_is(unsigned index, scmp_datum_t value) { return scmp_arg_cmp{index, SCMP_CMP_EQ, value, 0}; }

// What computing and answering need, and nothing that reaches out of the process. The dynamic
// loader's open of the shared object, and fstat's newfstatat, go to the listener and on from there.
int add_allowlist(scmp_filter_ctx filter) {
  const int plain[] = {
      SCMP_SYS(read), SCMP_SYS(write), SCMP_SYS(readv), SCMP_SYS(writev), SCMP_SYS(pread64), SCMP_SYS(lseek),
      SCMP_SYS(fstat), SCMP_SYS(close), SCMP_SYS(recvfrom), SCMP_SYS(sendto),              // the socket, and printing
      SCMP_SYS(mmap), SCMP_SYS(munmap), SCMP_SYS(mprotect), SCMP_SYS(mremap), SCMP_SYS(madvise), SCMP_SYS(brk),
      SCMP_SYS(futex), SCMP_SYS(rt_sigaction), SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigreturn), SCMP_SYS(restart_syscall),
      SCMP_SYS(getpid), SCMP_SYS(gettid), SCMP_SYS(setitimer), SCMP_SYS(clock_gettime), SCMP_SYS(clock_getres),
      SCMP_SYS(gettimeofday), SCMP_SYS(time), SCMP_SYS(getrandom), SCMP_SYS(sched_yield),
      SCMP_SYS(exit), SCMP_SYS(exit_group),
  };
  for (const int call : plain)
    if (const int error = seccomp_rule_add(filter, SCMP_ACT_ALLOW, call, 0); error != 0) return error;
  const scmp_datum_t pid = scmp_datum_t(getpid());
  if (const int error = seccomp_rule_add(filter, SCMP_ACT_ALLOW, SCMP_SYS(sendmsg), 1, argument_is(0, kSocketDescriptor)))
    return error;  // handing the listener over
  if (const int error = seccomp_rule_add(filter, SCMP_ACT_ALLOW, SCMP_SYS(tgkill), 1, argument_is(0, pid)))
    return error;  // raise() and abort(), to itself
  return seccomp_rule_add(filter, SCMP_ACT_ALLOW, SCMP_SYS(prlimit64), 1, argument_is(2, 0));  // reading limits only
}

void failed(Sandbox& sandbox, const char* what, int error) {
  sandbox.message.status = kReplyFailed;
  std::snprintf(sandbox.message.message, sizeof sandbox.message.message, "%s: %s", what, std::strerror(error));
}

}  // namespace

Sandbox enter_sandbox(const std::string& shared_object) {
  Sandbox sandbox;
  if (!set_limits()) {
    failed(sandbox, "cannot set its limits (setrlimit)", errno);
    return sandbox;
  }
  sandbox.message.namespaces = enter_namespaces();

  LandlockRuleset ruleset;
  if (ruleset.active() && !ruleset.allow_reading(shared_object)) {
    failed(sandbox, "cannot open the shared object", errno);
    return sandbox;
  }
  if (const int error = ruleset.restrict_self(); error != 0) {
    failed(sandbox, "cannot restrict itself (no_new_privs, Landlock)", error);
    return sandbox;
  }
  sandbox.message.landlock_abi = ruleset.active() ? ruleset.abi() : 0;

  const Filter filter(seccomp_init(SCMP_ACT_NOTIFY), &seccomp_release);
  if (!filter) {
    failed(sandbox, "cannot make a seccomp filter", ENOMEM);
    return sandbox;
  }
  int error = seccomp_attr_set(filter.get(), SCMP_FLTATR_ACT_BADARCH, SCMP_ACT_KILL_PROCESS);
  if (error == 0) error = add_allowlist(filter.get());
  if (error == 0) error = seccomp_load(filter.get());
  if (error != 0) {
    failed(sandbox, "cannot load its seccomp filter (Linux 5.5 or later, with seccomp's listeners)", -error);
    return sandbox;
  }
  sandbox.listener.reset(seccomp_notify_fd(filter.get()));
  if (!sandbox.listener.valid()) failed(sandbox, "its seccomp filter has no listener", EINVAL);
  return sandbox;
}

}  // namespace impulse::workshop
