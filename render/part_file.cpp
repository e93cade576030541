#include "render/part_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

namespace impulse::render {
namespace {

namespace fs = std::filesystem;

// What is at `path`, for a refusal; empty for a regular file or nothing at all.
std::string not_a_regular_file(const std::string& path) {
  struct stat status {};
  if (lstat(path.c_str(), &status) != 0) return "";
  switch (status.st_mode & S_IFMT) {
    case S_IFREG: return "";
    case S_IFDIR: return "a directory";
    case S_IFCHR: return "a character device";
    case S_IFBLK: return "a block device";
    case S_IFIFO: return "a FIFO";
    case S_IFSOCK: return "a socket";
    case S_IFLNK: return "a symbolic link";
    default: return "not a regular file";
  }
}

void refuse_unless_regular(const std::string& path, const std::string& shown_as) {
  const std::string what = not_a_regular_file(path);
  if (what.empty()) return;
  throw OutputError(shown_as + " is " + what + ": impulse replaces only regular files; choose another output path");
}

// Follows symbolic links to what they name, so that the link is kept and its file replaced.
std::string resolve_links(const std::string& path) {
  std::error_code error;
  if (!fs::is_symlink(fs::symlink_status(path, error))) return path;
  const fs::path target = fs::canonical(path, error);
  if (error) throw OutputError(path + " is a symbolic link to nothing (" + error.message() + "); choose another output path");
  return target.string();
}

// Slots a signal handler can read without locks: a path is copied in before its slot is marked
// ready, and the slot is freed only after it is unmarked.
struct SignalSlot {
  std::atomic<bool> taken{false};
  std::atomic<bool> ready{false};
  char path[4096] = {};
};
std::array<SignalSlot, 64> signal_slots;

int register_for_signals(const std::string& path) {
  if (path.size() >= sizeof(SignalSlot::path)) return -1;
  for (int i = 0; i < static_cast<int>(signal_slots.size()); ++i) {
    SignalSlot& slot = signal_slots[i];
    bool expected = false;
    if (!slot.taken.compare_exchange_strong(expected, true)) continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.ready.store(true);
    return i;
  }
  return -1;  // more files at once than slots: the rest are removed by their destructors only
}

void unregister_for_signals(int index) {
  if (index < 0) return;
  signal_slots[index].ready.store(false);
  signal_slots[index].taken.store(false);
}

}  // namespace

PartFile::PartFile(std::string final_path)
    : final_path_(resolve_links(final_path)), part_path_(final_path_ + ".part") {
  refuse_unless_regular(final_path_, final_path_);
  refuse_unless_regular(part_path_, part_path_);
  std::remove(part_path_.c_str());  // a regular file left by a run that was killed
  signal_slot_ = register_for_signals(part_path_);
}

PartFile::~PartFile() {
  if (!committed_) std::remove(part_path_.c_str());
  unregister_for_signals(signal_slot_);
}

void PartFile::commit() {
  refuse_unless_regular(final_path_, final_path_);  // it may have changed during a long render
  if (std::rename(part_path_.c_str(), final_path_.c_str()) != 0) {
    throw OutputError("cannot rename " + part_path_ + " to " + final_path_ + ": " + std::strerror(errno));
  }
  committed_ = true;
}

void remove_unfinished_part_files() noexcept {
  for (SignalSlot& slot : signal_slots) {
    if (slot.ready.load()) unlink(slot.path);
  }
}

}  // namespace impulse::render
