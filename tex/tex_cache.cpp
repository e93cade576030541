#include "tex/tex_cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace impulse::tex {
namespace {

std::string default_directory() {
  if (const char* own = std::getenv("IMPULSE_TEX_CACHE"); own != nullptr && *own != '\0') return own;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg == '/') return std::string(xdg) + "/impulse/tex";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') return std::string(home) + "/.cache/impulse/tex";
  return (std::filesystem::temp_directory_path() / "impulse-tex-cache").string();
}

}  // namespace

std::string text_hash(const std::string& text) {
  uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

TexCache::TexCache(std::string directory) : directory_(directory.empty() ? default_directory() : std::move(directory)) {}

std::optional<std::string> TexCache::read(const std::string& key) const {
  std::ifstream file(path_of(key), std::ios::binary);
  if (!file) return std::nullopt;
  std::ostringstream text;
  text << file.rdbuf();
  std::string svg = text.str();
  // A whole file ends with the SVG's closing tag (files are renamed into place only when whole).
  if (svg.find("</svg>") == std::string::npos) return std::nullopt;
  return svg;
}

bool TexCache::write(const std::string& key, const std::string& svg) const {
  static std::atomic<unsigned> counter{0};
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  const std::string temporary =
      path_of(key) + "." + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".tmp";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) return false;
    file << svg;
    file.flush();
    if (!file) {
      std::filesystem::remove(temporary, error);
      return false;
    }
  }
  std::filesystem::rename(temporary, path_of(key), error);
  if (!error) return true;
  std::filesystem::remove(temporary, error);
  return false;
}

}  // namespace impulse::tex
