#include "render/shader_cache.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>

namespace impulse::render {
namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

// Mesa reads the width with strtol and falls back to its default when nothing parses.
std::string vector_width_name() {
  const std::string text = environment("LP_NATIVE_VECTOR_WIDTH");
  char* end = nullptr;
  const long width = std::strtol(text.c_str(), &end, 0);
  return end != text.c_str() ? std::to_string(width) : "default";
}

// Mesa's own choice of cache directory (util/disk_cache_os.c), empty when it has none.
std::filesystem::path mesa_cache_directory() {
  if (const std::string own = environment("MESA_SHADER_CACHE_DIR"); !own.empty()) return own;
  if (const std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) {
    return std::filesystem::path(xdg) / "mesa_shader_cache";
  }
  if (const std::string home = environment("HOME"); !home.empty()) {
    return std::filesystem::path(home) / ".cache" / "mesa_shader_cache";
  }
  return {};
}

}  // namespace

void separate_shader_cache_by_vector_width() {
  static std::once_flag once;
  std::call_once(once, [] {
    const std::filesystem::path base = mesa_cache_directory();
    const std::filesystem::path directory = base / ("impulse-vector-width-" + vector_width_name());
    std::error_code error;
    if (base.empty() || (std::filesystem::create_directories(directory, error), error)) {
      setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);  // no cache is slower, never wrong
      return;
    }
    setenv("MESA_SHADER_CACHE_DIR", directory.c_str(), 1);
  });
}

}  // namespace impulse::render
