#include "tests/fuzz/scene_input.h"

#include <sys/mman.h>
#include <unistd.h>

#include <stdexcept>
#include <string_view>

#include "demos/scene/scene_file.h"

namespace impulse::fuzz {
namespace {

// An in-memory regular file (memfd), rewritten for each input: load_scene reads a path, and
// /proc/self/fd/N is one without touching the disk. One per process; the fuzzer runs one thread.
class MemoryFile {
 public:
  MemoryFile() : fd_(memfd_create("impulse_fuzz_scene.toml", MFD_CLOEXEC)) {
    if (fd_ < 0) throw std::runtime_error("memfd_create failed");
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  ~MemoryFile() { close(fd_); }
  const std::string& write(const std::string& text) {
    if (ftruncate(fd_, 0) != 0) throw std::runtime_error("ftruncate failed");
    for (size_t done = 0; done < text.size();) {
      const ssize_t n = pwrite(fd_, text.data() + done, text.size() - done, off_t(done));
      if (n <= 0) throw std::runtime_error("pwrite failed");
      done += size_t(n);
    }
    return path_;
  }

 private:
  int fd_;
  std::string path_;
};

}  // namespace

SceneInput split_input(const uint8_t* data, size_t size) {
  SceneInput input;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  size_t separator = std::string_view::npos;
  if (all.starts_with("%%\n")) separator = 0;
  else if (const size_t at = all.find("\n%%\n"); at != std::string_view::npos) separator = at + 1;
  if (separator == std::string_view::npos) {
    input.text = std::string(all);
    return input;
  }
  for (size_t begin = 0; begin < separator;) {
    const size_t end = all.find('\n', begin);
    input.settings.emplace_back(all.substr(begin, end - begin));
    begin = end + 1;
  }
  input.text = std::string(all.substr(separator + 3));
  return input;
}

bool load_input(const SceneInput& input) {
  static MemoryFile file;
  const std::string& path = file.write(input.text);
  try {
    const demos::Scene scene = demos::load_scene(path, input.settings);
    (void)demos::find_body(scene, "ball");
    return true;
  } catch (const demos::SceneError&) {
    return false;
  }
}

}  // namespace impulse::fuzz
