// [camera] (with follow and [[camera.keyframe]]), [video], [draw], [overlay], [[caption]] (read after [compare], as a caption may name a pane) and
// [playback]: what the video shows and how it is encoded.
#include "demos/scene/scene_sections.h"
#include "demos/scene/video_quality.h"

#include <algorithm>
#include <cstdio>

namespace impulse::demos {

namespace {

// A field naming a body: empty, or the name of one (checked here, at the field's own line).
std::string no_such_body(const std::string& name, const Scene& scene) {
  std::string known;
  for (const physics::BodyDef& body : scene.bodies) known += (known.empty() ? "'" : ", '") + body.name + "'";
  return "no body is named '" + name + "' (bodies: " + known + ")";
}

std::string body_name(TableReader& r, std::string_view key, const Scene& scene) {
  const std::string name = r.string(key, "");
  if (name.empty() || find_body(scene, name) >= 0) return name;
  r.fail(r.get(key), key, no_such_body(name, scene));
}

CameraSetting read_camera_fields(TableReader& r, CameraSetting camera) {
  camera.position = r.vec3("position", camera.position.cast<physics::Real>()).cast<float>();
  camera.target = r.vec3("target", camera.target.cast<physics::Real>()).cast<float>();
  camera.fov_y_degrees = float(r.number("fov", camera.fov_y_degrees, 1, 170));
  if ((camera.position - camera.target).norm() < 1e-6f) r.fail(r.get("target"), "target", "must differ from position");
  return camera;
}

void read_camera(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("camera");
  if (!t) return;
  TableReader r = top.child(*t, "[camera]");
  scene.camera = read_camera_fields(r, scene.camera);
  scene.camera_motion.follow = body_name(r, "follow", scene);
  if (const toml::node* node = r.get("keyframe")) {
    const toml::array* keyframes = node->as_array();
    if (!keyframes || !keyframes->is_array_of_tables())
      r.fail(node, "keyframe", "must be a list of [[camera.keyframe]] tables");
    CameraSetting previous = scene.camera;
    double previous_time = 0;
    for (const toml::node& item : *keyframes) {
      TableReader k = r.child(*item.as_table(), "[[camera.keyframe]]");
      CameraKeyframe keyframe;
      keyframe.time = k.number("time", -1, 0, 3600, true);
      if (keyframe.time < 0) k.fail(nullptr, "time", "missing: when (s) the camera is there");
      if (keyframe.time <= previous_time)
        k.fail(k.get("time"), "time", "keyframes must come in increasing time, after 0 (the [camera] fields)");
      keyframe.camera = read_camera_fields(k, previous);  // unset fields keep the previous keyframe's
      k.finish();
      scene.camera_motion.keyframes.push_back(keyframe);
      previous = keyframe.camera;
      previous_time = keyframe.time;
    }
  }
  if (!scene.camera_motion.follow.empty() && !scene.camera_motion.keyframes.empty())
    r.fail(r.get("follow"), "follow", "use either follow or [[camera.keyframe]], not both");
  scene.camera_motion.fit = r.boolean("fit", false);
  if (scene.camera_motion.fit && (!scene.camera_motion.follow.empty() || !scene.camera_motion.keyframes.empty()))
    r.fail(r.get("fit"), "fit", "frames the whole run from one place: not with follow or [[camera.keyframe]]");
  r.finish();
}

void read_video(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("video");
  if (!t) return;
  TableReader r = top.child(*t, "[video]");
  auto& v = scene.video;
  const std::string quality = r.choice("quality", "medium", {"low", "medium", "high"});
  v = *quality_preset(quality);
  v.width = r.integer("width", v.width, 16, 7680);
  v.height = r.integer("height", v.height, 16, 4320);
  if (v.width % 2 || v.height % 2) r.fail(r.get("width"), "width", "width and height must be even (yuv420p)");
  v.fps = r.integer("fps", v.fps, 1, 240);
  v.crf = r.integer("crf", v.crf, 0, 51);
  v.preset = r.choice("x264_preset", v.preset,
                      {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"});
  r.finish();
}

void read_draw(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("draw");
  if (!t) return;
  TableReader r = top.child(*t, "[draw]");
  DrawOptions& d = scene.draw;
  d.contact_points = r.boolean("contact_points", d.contact_points);
  d.contact_normals = r.boolean("contact_normals", d.contact_normals);
  d.normal_length = float(r.number("normal_length", d.normal_length, 0, 100, true));
  d.impulses = r.boolean("impulses", d.impulses);
  d.friction = r.boolean("friction", d.friction);
  d.impulse_scale = float(r.number("impulse_scale", d.impulse_scale, 0, 1e6));
  d.contact_hold = float(r.number("contact_hold", d.contact_hold, 0, 10));
  d.velocities = r.boolean("velocities", d.velocities);
  d.velocity_scale = float(r.number("velocity_scale", d.velocity_scale, 0, 1e6));
  d.sleeping = r.boolean("sleeping", d.sleeping);
  d.marked_pairs = r.integer("marked_pairs", d.marked_pairs, 0, 1'000'000);
  d.faint_below = float(r.number("faint_below", d.faint_below, 0, 1));
  r.finish();
}

void read_overlay(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("overlay");
  if (!t) return;
  TableReader r = top.child(*t, "[overlay]");
  OverlayOptions& o = scene.overlay;
  o.title = r.boolean("title", o.title);
  o.clock = r.boolean("clock", o.clock);
  o.legend = r.boolean("legend", o.legend);
  if (const toml::node* node = r.get("plots")) {
    const char* expected = "must be a list of plot names, like [\"kinetic_energy\", \"momentum\", \"speed\"]";
    const toml::array* plots = node->as_array();
    if (!plots) r.fail(node, "plots", expected);
    o.plots.clear();
    for (const toml::node& item : *plots) {
      const auto name = item.value_exact<std::string>();
      if (!name) r.fail(node, "plots", expected);
      if (*name == "kinetic_energy") o.plots.push_back(PlotKind::kinetic_energy);
      else if (*name == "momentum") o.plots.push_back(PlotKind::momentum);
      else if (*name == "speed") o.plots.push_back(PlotKind::speed);
      else r.fail(node, "plots", "unknown plot '" + *name + "' (known: kinetic_energy, momentum, speed)");
    }
  }
  // One body's name, or several: the "speed" plot's curves.
  if (const toml::node* node = r.get("plot_body"); node && node->is_array()) {
    const char* expected = "must be a body's name or a list of them, like [\"solid ball\", \"hollow ball\"]";
    o.plot_bodies.clear();
    for (const toml::node& item : *node->as_array()) {
      const auto name = item.value_exact<std::string>();
      if (!name || find_body(scene, *name) < 0) r.fail(node, "plot_body", name ? no_such_body(*name, scene) : std::string(expected));
      o.plot_bodies.push_back(*name);
    }
    if (o.plot_bodies.empty()) r.fail(node, "plot_body", expected);
  } else if (const std::string name = body_name(r, "plot_body", scene); !name.empty()) {
    o.plot_bodies = {name};
  }
  o.plot_from = r.number("plot_from", o.plot_from, 0);
  if (o.plot_from >= scene.duration) {
    char duration[32];
    std::snprintf(duration, sizeof duration, "%g", scene.duration);
    r.fail(r.get("plot_from"), "plot_from", std::string("must come before the scene's end ([scene] duration = ") + duration + " s)");
  }
  o.label = r.choice("label", o.label, {"impulse", "velocity", "none"});
  o.label_body = body_name(r, "label_body", scene);
  o.equation = r.choice("equation", o.equation, {"none", "eq8", "eq13"});
  r.finish();
}

}  // namespace

bool names_the_pane(const std::string& text) { return text.find("{value}") != std::string::npos || text.find("{label}") != std::string::npos; }

void read_captions(TableReader& top, Scene& scene) {
  const toml::array* captions = top.table_list("caption");
  if (!captions) return;
  for (const toml::node& item : *captions) {
    TableReader r = top.child(*item.as_table(), "[[caption]]");
    CaptionCue cue;
    cue.text = r.string("text", "");
    if (cue.text.empty()) r.fail(r.get("text"), "text", "missing: the caption's words, in quotes");
    cue.start = r.number("start", 0, 0);
    cue.end = r.number("end", scene.duration, 0);
    if (cue.end <= cue.start) r.fail(r.get("end"), "end", "must come after start");
    const int panes = int(scene.compare.values.size());
    cue.pane = r.integer("pane", 0, 0, 4);
    if (cue.pane > panes)
      r.fail(r.get("pane"), "pane", panes == 0 ? "the scene has no [compare] table, so no panes"
                                              : "the [compare] table has " + std::to_string(panes) + " panes");
    if (panes == 0 && names_the_pane(cue.text))
      r.fail(r.get("text"), "text", "names a pane's {value} or {label}, but the scene has no [compare] table, so no panes");
    r.finish();
    scene.captions.push_back(cue);
  }
}

namespace {

void read_playback(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("playback");
  if (!t) return;
  TableReader r = top.child(*t, "[playback]");
  PlaybackOptions& p = scene.playback;
  p.speed = r.number("speed", p.speed, 0.01, 100);
  p.slow_motion_impulse = r.number("slow_motion_impulse", p.slow_motion_impulse, 0);
  p.slow_motion_speed = r.number("slow_motion_speed", p.slow_motion_speed, 0.01, 1);
  p.slow_motion_window = r.number("slow_motion_window", p.slow_motion_window, 0, 10, true);
  if (r.get("poster")) p.poster = r.number("poster", 0, 0, scene.duration);
  r.finish();
}

}  // namespace

void read_view(TableReader& top, Scene& scene) {
  read_camera(top, scene);
  read_video(top, scene);
  read_draw(top, scene);
  read_overlay(top, scene);
  read_playback(top, scene);
}

}  // namespace impulse::demos
