#include "demos/response/landlock.h"

#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace impulse::workshop {

namespace {

// The kernel's ABI, as numbers: Debian 12's headers stop at ABI 2 (linux/landlock.h has the
// calls' numbers and the first rights).
constexpr uint64_t kExecute = 1ULL << 0, kWriteFile = 1ULL << 1, kReadFile = 1ULL << 2, kReadDir = 1ULL << 3;
constexpr uint64_t kAbiOneRights = (1ULL << 13) - 1;  // execute .. make symlink
constexpr uint64_t kRefer = 1ULL << 13;               // ABI 2
constexpr uint64_t kTruncate = 1ULL << 14;            // ABI 3
constexpr uint64_t kIoctlDevice = 1ULL << 15;         // ABI 5
constexpr uint64_t kFileRights = kExecute | kWriteFile | kReadFile | kTruncate | kIoctlDevice;  // what a rule on a file may hold
constexpr uint64_t kNetBindTcp = 1ULL << 0, kNetConnectTcp = 1ULL << 1;                          // ABI 4
constexpr uint64_t kScopeAbstractUnixSocket = 1ULL << 0, kScopeSignal = 1ULL << 1;               // ABI 6

struct RulesetAttributes {  // struct landlock_ruleset_attr as ABI 6 has it; older kernels take its first fields
  uint64_t handled_access_fs = 0;
  uint64_t handled_access_net = 0;
  uint64_t scoped = 0;
};

uint64_t file_system_rights(int abi) {
  uint64_t rights = kAbiOneRights;
  if (abi >= 2) rights |= kRefer;
  if (abi >= 3) rights |= kTruncate;
  if (abi >= 5) rights |= kIoctlDevice;
  return rights;
}

}  // namespace

int landlock_abi() {
  const long abi = syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return abi < 0 ? 0 : int(abi);
}

LandlockRuleset::LandlockRuleset() : abi_(landlock_abi()) {
  if (abi_ < 1) return;
  RulesetAttributes attributes;
  attributes.handled_access_fs = handled_ = file_system_rights(abi_);
  size_t size = sizeof attributes.handled_access_fs;
  if (abi_ >= 4) {
    attributes.handled_access_net = kNetBindTcp | kNetConnectTcp;
    size += sizeof attributes.handled_access_net;
  }
  if (abi_ >= 6) {
    attributes.scoped = kScopeAbstractUnixSocket | kScopeSignal;
    size += sizeof attributes.scoped;
  }
  const long fd = syscall(SYS_landlock_create_ruleset, &attributes, size, 0);
  if (fd >= 0) fd_.reset(int(fd));
}

bool LandlockRuleset::allow(const std::string& path, unsigned long long file_rights, unsigned long long directory_rights) {
  if (!active()) return false;
  const UniqueFd parent(open(path.c_str(), O_PATH | O_CLOEXEC));
  struct stat info {};
  if (!parent.valid() || fstat(parent.get(), &info) != 0) return false;
  landlock_path_beneath_attr rule{};
  rule.allowed_access = (S_ISDIR(info.st_mode) ? file_rights | directory_rights : file_rights & kFileRights) & handled_;
  rule.parent_fd = parent.get();
  return syscall(SYS_landlock_add_rule, fd_.get(), LANDLOCK_RULE_PATH_BENEATH, &rule, 0) == 0;
}

bool LandlockRuleset::allow_reading(const std::string& path, bool execute) {
  return allow(path, kReadFile | (execute ? kExecute : 0), kReadDir);
}

bool LandlockRuleset::allow_everything(const std::string& directory) { return allow(directory, handled_, handled_); }

bool LandlockRuleset::allow_reading_and_writing(const std::string& file) {
  return allow(file, kReadFile | kWriteFile | kTruncate | kIoctlDevice, 0);
}

int LandlockRuleset::restrict_self() const {
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return errno;
  if (active() && syscall(SYS_landlock_restrict_self, fd_.get(), 0) != 0) return errno;
  return 0;
}

}  // namespace impulse::workshop
