// [camera], [video] and [draw]: what the video shows and how it is encoded.
#include "demos/scene_sections.h"

namespace impulse::demos {

void read_view(TableReader& top, Scene& scene) {
  const std::string& path = scene.path;
  if (const toml::table* t = top.table("camera")) {
    TableReader r(*t, path, "[camera]");
    auto& c = scene.camera;
    c.position = r.vec3("position", c.position.cast<physics::Real>()).cast<float>();
    c.target = r.vec3("target", c.target.cast<physics::Real>()).cast<float>();
    c.fov_y_degrees = float(r.number("fov", c.fov_y_degrees, 1, 170));
    if ((c.position - c.target).norm() < 1e-6f) r.fail(r.get("target"), "target", "must differ from position");
    r.finish();
  }
  if (const toml::table* t = top.table("video")) {
    TableReader r(*t, path, "[video]");
    auto& v = scene.video;
    v.width = r.integer("width", v.width, 16, 7680);
    v.height = r.integer("height", v.height, 16, 4320);
    if (v.width % 2 || v.height % 2) r.fail(r.get("width"), "width", "width and height must be even (yuv420p)");
    v.fps = r.integer("fps", v.fps, 1, 240);
    v.crf = r.integer("crf", v.crf, 0, 51);
    r.finish();
  }
  if (const toml::table* t = top.table("draw")) {
    TableReader r(*t, path, "[draw]");
    scene.draw.contact_normals = r.boolean("contact_normals", scene.draw.contact_normals);
    scene.draw.normal_length = float(r.number("normal_length", scene.draw.normal_length, 0, 100, true));
    r.finish();
  }
}

}  // namespace impulse::demos
