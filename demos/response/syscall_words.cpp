#include "demos/response/syscall_words.h"

#include <fcntl.h>
#include <seccomp.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

namespace impulse::workshop {

namespace {

enum class Kind { open, write, list, look, change, run, process, signal, network };

struct CallKind {
  Kind kind;
  int path = -1;   // the argument that holds the path, if any
  int flags = -1;  // open's flags
};

// Resolved by name, once: the numbers are the machine's.
const std::map<int, CallKind>& call_kinds() {
  static const std::map<int, CallKind> kinds = [] {
    const std::vector<std::pair<const char*, CallKind>> named = {
        {"open", {Kind::open, 0, 1}},         {"openat", {Kind::open, 1, 2}},          {"openat2", {Kind::open, 1}},
        {"creat", {Kind::write, 0}},         {"open_by_handle_at", {Kind::open}},     {"getdents", {Kind::list}},
        {"getdents64", {Kind::list}},         {"stat", {Kind::look, 0}},               {"lstat", {Kind::look, 0}},
        {"newfstatat", {Kind::look, 1}},      {"statx", {Kind::look, 1}},              {"access", {Kind::look, 0}},
        {"faccessat", {Kind::look, 1}},       {"faccessat2", {Kind::look, 1}},         {"readlink", {Kind::look, 0}},
        {"readlinkat", {Kind::look, 1}},      {"statfs", {Kind::look, 0}},             {"getxattr", {Kind::look, 0}},
        {"unlink", {Kind::change, 0}},        {"unlinkat", {Kind::change, 1}},         {"rename", {Kind::change, 0}},
        {"renameat", {Kind::change, 1}},      {"renameat2", {Kind::change, 1}},        {"mkdir", {Kind::change, 0}},
        {"mkdirat", {Kind::change, 1}},       {"rmdir", {Kind::change, 0}},            {"link", {Kind::change, 1}},
        {"linkat", {Kind::change, 3}},        {"symlink", {Kind::change, 1}},          {"symlinkat", {Kind::change, 2}},
        {"chmod", {Kind::change, 0}},         {"fchmodat", {Kind::change, 1}},         {"chown", {Kind::change, 0}},
        {"lchown", {Kind::change, 0}},        {"fchownat", {Kind::change, 1}},         {"truncate", {Kind::change, 0}},
        {"ftruncate", {Kind::change}},        {"mknod", {Kind::change, 0}},            {"mknodat", {Kind::change, 1}},
        {"utimensat", {Kind::change, 1}},     {"setxattr", {Kind::change, 0}},         {"execve", {Kind::run, 0}},
        {"execveat", {Kind::run, 1}},         {"fork", {Kind::process}},               {"vfork", {Kind::process}},
        {"clone", {Kind::process}},           {"clone3", {Kind::process}},             {"kill", {Kind::signal}},
        {"tkill", {Kind::signal}},            {"tgkill", {Kind::signal}},              {"rt_sigqueueinfo", {Kind::signal}},
        {"rt_tgsigqueueinfo", {Kind::signal}}, {"pidfd_send_signal", {Kind::signal}},  {"socket", {Kind::network}},
        {"socketpair", {Kind::network}},      {"connect", {Kind::network}},            {"bind", {Kind::network}},
        {"listen", {Kind::network}},          {"accept", {Kind::network}},             {"accept4", {Kind::network}},
    };
    std::map<int, CallKind> by_number;
    for (const auto& [name, kind] : named)
      if (const int number = seccomp_syscall_resolve_name(name); number >= 0) by_number[number] = kind;
    return by_number;
  }();
  return kinds;
}

std::string call_name(int number) {
  const std::unique_ptr<char, decltype(&std::free)> name(seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, number), &std::free);
  return name ? name.get() : "number " + std::to_string(number);
}

std::string with_path(const std::string& words, const std::string& path) {
  return path.empty() ? words : words + " (" + quoted_path(path) + ")";
}

}  // namespace

std::string quoted_path(const std::string& path) {
  std::string out = "'";
  for (size_t i = 0; i < path.size() && i < 200; ++i) {
    const unsigned char c = static_cast<unsigned char>(path[i]);
    if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\') {
      out += char(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    }
  }
  return out + (path.size() > 200 ? "...'" : "'");
}

std::string attempt_words(int number, const uint64_t (&arguments)[6], const std::function<std::string(uint64_t)>& read_text) {
  const auto found = call_kinds().find(number);
  if (found == call_kinds().end()) return "make the system call " + call_name(number);
  const CallKind& call = found->second;
  const std::string path = call.path >= 0 ? read_text(arguments[call.path]) : "";
  switch (call.kind) {
    case Kind::open: {
      const uint64_t flags = call.flags >= 0 ? arguments[call.flags] : 0;
      if (flags & O_DIRECTORY) return with_path("list a directory", path);
      if ((flags & O_ACCMODE) != O_RDONLY || (flags & (O_CREAT | O_TRUNC | O_APPEND))) return with_path("write a file", path);
      return with_path("open a file", path);
    }
    case Kind::write: return with_path("write a file", path);
    case Kind::list: return "list a directory";
    case Kind::look: return with_path("look at a file", path);
    case Kind::change: return with_path("change a file", path);
    case Kind::run: return with_path("run a program", path);
    case Kind::process: return "start a process (fork, system() or a thread)";
    case Kind::signal: return "send a signal to another process";
    case Kind::network: return "open a network socket";
  }
  return "make the system call " + call_name(number);
}

}  // namespace impulse::workshop
