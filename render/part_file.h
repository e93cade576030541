// Writing a file atomically: write to `path + ".part"`, then commit() renames it to `path`.
// Until commit() the final name is never touched; destroying an uncommitted PartFile deletes
// the .part file, so a failure leaves nothing behind.
//
// Only regular files are ever replaced. A final path that is a device, a FIFO, a directory or a
// socket is refused, in the constructor (before any work) and again at commit(). A symbolic link
// to a regular file is written through: the file it points to is replaced, the link stays.
#pragma once
#include <stdexcept>
#include <string>

namespace impulse::render {

// The output cannot be written: it names the path and the reason.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class PartFile {
 public:
  // Throws OutputError if `final_path` (or a .part file already there) must not be replaced.
  // A regular .part file left by a killed run is removed.
  explicit PartFile(std::string final_path);
  ~PartFile();
  PartFile(const PartFile&) = delete;
  PartFile& operator=(const PartFile&) = delete;

  const std::string& final_path() const { return final_path_; }
  const std::string& part_path() const { return part_path_; }

  void commit();  // renames .part to the final path; throws OutputError naming both

 private:
  std::string final_path_;  // symbolic links resolved
  std::string part_path_;
  int signal_slot_ = -1;
  bool committed_ = false;
};

// Deletes the .part file of every PartFile alive. Async-signal-safe: for a handler of SIGINT or
// SIGTERM that then ends the process, so that an interrupted render leaves no temporary behind.
void remove_unfinished_part_files() noexcept;

}  // namespace impulse::render
