// The on-disk cache of typeset mathematics: one SVG file per LaTeX document, named by the
// document's hash (as Manim names its Tex files), in
//   $IMPULSE_TEX_CACHE, else $XDG_CACHE_HOME/impulse/tex, else ~/.cache/impulse/tex.
// Writers never corrupt it: each writes a temporary of its own (name with its process id and a
// counter) and renames it over the final name, so a reader sees a whole file or none; two
// renders that typeset the same document write the same bytes, and the last rename wins.
#pragma once
#include <optional>
#include <string>

namespace impulse::tex {

// 16 hex digits: FNV-1a (64 bits) of `text`. Stable across builds and machines.
std::string text_hash(const std::string& text);

class TexCache {
 public:
  // The directory from the environment (above); `directory` non-empty overrides it.
  explicit TexCache(std::string directory = "");

  const std::string& directory() const { return directory_; }
  std::optional<std::string> read(const std::string& key) const;  // the SVG, if cached
  // Stores `svg` under `key`; false (and nothing written) when the directory cannot be written:
  // typesetting still works, only uncached.
  bool write(const std::string& key, const std::string& svg) const;
  std::string path_of(const std::string& key) const { return directory_ + "/" + key + ".svg"; }

 private:
  std::string directory_;
};

}  // namespace impulse::tex
