#include "demos/scene/scene_file.h"

#include "demos/scene/scene_overrides.h"
#include "demos/scene/scene_sections.h"
#include "demos/scene/toml_syntax.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace impulse::demos {
namespace {

constexpr std::uintmax_t kLargestFile = 16 << 20;  // bytes: scene files are text of a few kilobytes

// The file's text, or a SceneError saying why there is none: missing, a directory, too large,
// not text.
std::string read_scene_text(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) throw SceneError(path + ": no such scene file");
  if (fs::is_directory(status)) throw SceneError(path + ": is a directory, not a scene file (give a .toml file)");
  if (!fs::is_regular_file(status)) throw SceneError(path + ": is not a regular file (give a .toml file)");
  if (fs::file_size(path, error) > kLargestFile)
    throw SceneError(path + ": is larger than 16 MiB; a scene file is text of a few kilobytes");
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  if (!(text << file.rdbuf()) && fs::file_size(path, error) > 0)
    throw SceneError(path + ": cannot read the scene file");
  const std::string bytes = text.str();
  if (bytes.find_first_not_of(" \t\r\n") == std::string::npos)
    throw SceneError(path + ": the file is empty; a scene needs at least one [[body]] table");
  if (const size_t zero = bytes.find('\0'); zero != std::string::npos)
    throw SceneError(path + ": is not a text file (a zero byte at offset " + std::to_string(zero) + ")");
  return bytes;
}

}  // namespace

SceneFile::SceneFile(std::string path) : path_(std::move(path)) {
  const std::string text = read_scene_text(path_);
  try {
    root_ = toml::parse(text, path_);
  } catch (const toml::parse_error& error) {
    std::ostringstream message;
    const int line = int(error.source().begin.line);
    message << path_ << ':' << line << ": " << plain_syntax_error(error.description(), line, int(error.source().begin.column), text);
    if (error.description().find("utf-8") != std::string_view::npos) message << " (save the file as UTF-8)";
    if (error.description().find("escape sequence") != std::string_view::npos)
      message << " (in double quotes a backslash starts an escape: write LaTeX in single quotes, tex = '\\alpha')";
    throw SceneError(message.str(), ScenePlace{path_, line, "", "", ""});
  }
}

SceneFile::SceneFile(toml::table root, std::string name) : path_(std::move(name)), root_(std::move(root)) {}

Scene SceneFile::scene(const std::vector<std::string>& settings) const {
  // The settings write into a copy: the one parse serves every scene read from the file (each
  // pane of a comparison). Its nodes are paired with the parsed ones, which have the lines.
  toml::table root = root_;
  NodeOrigins origins;
  origins.arguments = apply_overrides(root, settings);
  origins.pair(root, root_);

  Scene scene;
  scene.path = path_;
  scene.settings = settings;
  TableReader top(root, path_, &origins, "scene");
  if (const toml::table* t = top.table("scene")) {
    TableReader r = top.child(*t, "[scene]");
    scene.title = r.string("title", "");
    scene.duration = r.number("duration", scene.duration, 0, 3600, true);
    r.finish();
  }
  read_world(top, scene);
  read_bodies(top, scene);
  read_patterns(top, scene);
  read_material_pairs(top, scene);
  read_joints(top, scene);
  read_view(top, scene);  // after the bodies, whose names it checks
  read_compare(top, scene);
  read_equations(top, scene);  // after [playback], and [compare]: an equation may name a pane
  read_captions(top, scene);
  read_checks(top, scene);
  top.finish();
  if (scene.bodies.empty())
    throw SceneError(path_ + ": scene: no bodies; add at least one [[body]] table (or a [[pyramid]] or [[lattice]])",
                     ScenePlace{path_, 0, "", "", ""});
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& settings) {
  return SceneFile(path).scene(settings);
}

}  // namespace impulse::demos
