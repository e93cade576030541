#include "demos/scene/scene_file.h"

#include "demos/scene/scene_overrides.h"
#include "demos/scene/scene_sections.h"

#include <sstream>

namespace impulse::demos {

Scene load_scene(const std::string& path, const std::vector<std::string>& settings) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& error) {
    std::ostringstream message;
    if (error.source().begin.line == 0)
      message << path << ": cannot read the scene file (" << error.description() << ")";
    else
      message << path << ':' << error.source().begin.line << ": " << error.description();
    throw SceneError(message.str());
  }

  const OverrideNodes written = apply_overrides(root, settings);
  const OverrideScope scope(written);

  Scene scene;
  scene.path = path;
  scene.settings = settings;
  TableReader top(root, path, "scene");
  if (const toml::table* t = top.table("scene")) {
    TableReader r(*t, path, "[scene]");
    scene.title = r.string("title", "");
    scene.duration = r.number("duration", scene.duration, 0, 3600, true);
    r.finish();
  }
  read_world(top, scene);
  read_bodies(top, scene);
  read_patterns(top, scene);
  read_joints(top, scene);
  read_view(top, scene);  // after the bodies, whose names it checks
  top.finish();
  if (scene.bodies.empty()) throw SceneError(path + ":1: scene: no bodies; add at least one [[body]] table");
  return scene;
}

int find_body(const Scene& scene, std::string_view name) {
  for (size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].name == name) return int(i);
  return -1;
}

}  // namespace impulse::demos
