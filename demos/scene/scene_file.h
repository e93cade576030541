// Scene files (TOML) read into scenes (scene.h). A file is read and parsed once; each scene read
// from it (the file's own, and each pane of a comparison: scene_compare.h) is a copy of the
// parsed tables with its --set arguments written over them (scene_overrides.h), then checked
// field by field. The format is described in docs/scene_files.md.
#pragma once
#include "demos/scene/scene.h"
#include "demos/scene/scene_error.h"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace impulse::demos {

class SceneFile {
 public:
  // Reads and parses the file. Throws SceneError when it cannot: missing, a directory, too large,
  // not text, not TOML (with its line).
  explicit SceneFile(std::string path);
  // Tables built in memory (Python's dicts, demos/python/), as the file's would be parsed; `name`
  // stands for the file in messages, and relative paths in it are the current directory's.
  SceneFile(toml::table root, std::string name);

  const std::string& path() const { return path_; }
  // The scene with `settings` (--set KEY=VALUE) over the file. Throws SceneError naming the file,
  // line and field, or the --set argument.
  Scene scene(const std::vector<std::string>& settings = {}) const;

 private:
  std::string path_;
  toml::table root_;
};

// SceneFile(path).scene(settings): one scene from one file.
Scene load_scene(const std::string& path, const std::vector<std::string>& settings = {});

}  // namespace impulse::demos
