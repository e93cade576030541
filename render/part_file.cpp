#include "render/part_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
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


// The process id in a temporary's name NAME.PID-N.part, if `file_name` has that form.
std::optional<pid_t> writer_of(const std::string& file_name) {
  const std::string suffix = ".part";
  if (file_name.size() <= suffix.size() || file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const std::string stem = file_name.substr(0, file_name.size() - suffix.size());
  const size_t dot = stem.rfind('.');
  if (dot == std::string::npos || dot == 0) return std::nullopt;
  const std::string id = stem.substr(dot + 1);  // PID-N
  const size_t dash = id.find('-');
  const auto all_digits = [](const std::string& text) {
    return !text.empty() && text.size() <= 10 && text.find_first_not_of("0123456789") == std::string::npos;
  };
  if (dash == std::string::npos || !all_digits(id.substr(0, dash)) || !all_digits(id.substr(dash + 1))) return std::nullopt;
  return static_cast<pid_t>(std::stoll(id.substr(0, dash)));
}

// A temporary may be removed when its writer is gone: nobody holds its lock (a lock dies with its
// process, also on SIGKILL) and its process id is not alive (a writer that has created its file but
// not yet locked it is alive). A file that is not regular, or that we cannot open, is left alone.
void remove_if_writer_died(const fs::path& path, pid_t writer) {
  if (kill(writer, 0) == 0 || errno != ESRCH) return;
  const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return;
  struct stat status {};
  if (fstat(fd, &status) == 0 && S_ISREG(status.st_mode) && flock(fd, LOCK_EX | LOCK_NB) == 0) unlink(path.c_str());
  close(fd);
}

void remove_dead_writers_temporaries(const fs::path& directory) {
  std::error_code error;
  fs::directory_iterator entries(directory.empty() ? fs::path(".") : directory, error);
  if (error) return;  // an unreadable directory: the temporary's creation reports it
  for (const fs::directory_entry& entry : entries) {
    const std::optional<pid_t> writer = writer_of(entry.path().filename().string());
    if (writer && *writer != getpid()) remove_if_writer_died(entry.path(), *writer);
  }
}

// Creates FINAL.PID-N.part exclusively and locks it; returns its descriptor and path.
std::pair<int, std::string> create_own_temporary(const std::string& final_path) {
  static std::atomic<unsigned> next_number{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string path = final_path + "." + std::to_string(getpid()) + "-" + std::to_string(next_number++) + ".part";
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno == EEXIST) continue;  // taken: left by an earlier process with this id
    if (fd < 0) throw OutputError("cannot write " + final_path + " (its temporary " + path + "): " + std::strerror(errno));
    if (flock(fd, LOCK_EX) != 0) {
      const std::string reason = std::strerror(errno);
      close(fd);
      unlink(path.c_str());
      throw OutputError("cannot lock " + path + ": " + reason);
    }
    return {fd, path};
  }
  throw OutputError("cannot create a temporary beside " + final_path + ": 100 names taken");
}

}  // namespace

PartFile::PartFile(std::string final_path) : final_path_(resolve_links(final_path)) {
  refuse_unless_regular(final_path_, final_path_);
  remove_dead_writers_temporaries(fs::path(final_path_).parent_path());
  const auto [fd, path] = create_own_temporary(final_path_);
  lock_fd_ = fd;
  part_path_ = path;
  signal_slot_ = register_for_signals(part_path_);
}

PartFile::~PartFile() {
  if (!committed_) unlink(part_path_.c_str());
  unregister_for_signals(signal_slot_);
  close(lock_fd_);
}

void PartFile::commit() {
  refuse_unless_regular(final_path_, final_path_);  // it may have changed during a long render
  if (std::rename(part_path_.c_str(), final_path_.c_str()) != 0) {
    throw OutputError("cannot rename " + part_path_ + " to " + final_path_ + ": " + std::strerror(errno));
  }
  committed_ = true;
}

void write_file(const std::string& path, const std::function<void(std::ostream&)>& write) {
  std::error_code error;
  if (const std::filesystem::path parent = std::filesystem::path(path).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent, error);  // what cannot be made, PartFile reports
  PartFile part(path);
  std::ofstream out(part.part_path(), std::ios::binary | std::ios::trunc);
  if (!out) throw OutputError("cannot open " + part.part_path() + " for writing: " + std::strerror(errno));
  write(out);
  out.close();
  if (!out) throw OutputError("cannot write " + part.part_path() + ": " + std::strerror(errno));
  part.commit();
}

bool is_part_file_name(const std::string& file_name) { return writer_of(file_name).has_value(); }

int remove_unfinished_part_files() noexcept {
  int removed = 0;
  for (SignalSlot& slot : signal_slots) {
    if (slot.ready.load()) removed += unlink(slot.path) == 0;
  }
  return removed;
}

}  // namespace impulse::render
