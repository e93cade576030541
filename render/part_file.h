// Writing a file atomically, with any number of writers at once: each PartFile writes its own
// temporary beside the output, `path.PID-N.part`, and commit() renames it over `path`. A rename
// is atomic, so `path` is always either the previous file or one complete new one; when several
// writers finish, the last rename wins and each reports what it did. Until commit() the final name
// is never touched; destroying an uncommitted PartFile deletes its temporary.
//
// The temporary is created exclusively and held under an flock(2) lock for the writer's life.
// A temporary whose writer died without cleaning up (SIGKILL, a power cut) is removed by the next
// PartFile made in that directory: only files of this naming pattern, only while no process holds
// their lock and their process id is not alive.
//
// Only regular files are ever replaced. A final path that is a device, a FIFO, a directory or a
// socket is refused, in the constructor (before any work) and again at commit(). A symbolic link
// to a regular file is written through: the file it points to is replaced, the link stays.
#pragma once
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>

namespace impulse::render {

// The output cannot be written: it names the path and the reason.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class PartFile {
 public:
  // Throws OutputError if `final_path` must not be replaced or its temporary cannot be created.
  explicit PartFile(std::string final_path);
  ~PartFile();
  PartFile(const PartFile&) = delete;
  PartFile& operator=(const PartFile&) = delete;

  const std::string& final_path() const { return final_path_; }
  const std::string& part_path() const { return part_path_; }  // this writer's own temporary

  void commit();  // renames the temporary to the final path; throws OutputError naming both

 private:
  std::string final_path_;  // symbolic links resolved
  std::string part_path_;
  int lock_fd_ = -1;  // holds the temporary's flock until the writer is done
  int signal_slot_ = -1;
  bool committed_ = false;
};

// A file written whole or not at all: its directory made, `write` into a PartFile's temporary
// (binary), then committed. Throws OutputError when it cannot be opened, written or renamed, and
// whatever `write` throws (the temporary then deleted).
void write_file(const std::string& path, const std::function<void(std::ostream&)>& write);

// Whether `file_name` (no directory) is a temporary of a PartFile: NAME.PID-N.part.
bool is_part_file_name(const std::string& file_name);

// Deletes the temporary of every PartFile alive; how many there were. Async-signal-safe: for a
// handler of SIGINT or SIGTERM that then ends the process, so that an interrupted render leaves no
// temporary behind.
int remove_unfinished_part_files() noexcept;

}  // namespace impulse::render
