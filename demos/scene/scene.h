// A scene as a lecturer writes it in a scene file (TOML): the world, its bodies, the camera, the
// video, what frames show, captions, equations, checks and comparison. Plain data; the loader is
// scene_file.h, the format docs/scene_files.md.
#pragma once
#include "demos/scene/equation_cue.h"
#include "demos/scene/scene_checks.h"
#include "demos/scene/view_options.h"
#include "physics/world.h"

#include <string>
#include <string_view>
#include <vector>

namespace impulse::demos {

// [draw]: the physics made visible, each switchable (colours: demos/README.md, "What a frame shows").
struct DrawOptions {
  bool contact_points = true;    // a dot at each contact point
  bool contact_normals = true;   // an arrow along each contact's normal while it lasts
  float normal_length = 0.0f;    // m; 0: 1.5 times the smallest moving body's radius or half-size
  bool impulses = true;          // the normal impulse on each moving body, as an arrow
  bool friction = true;          // the friction (tangential) impulse, as an arrow
  float impulse_scale = 0.0f;    // m of arrow per N s; 0: chosen so the largest impulse is about 1.5 m
  float contact_hold = 0.4f;     // s of video a contact stays drawn after its step (impacts last one step)
  bool velocities = false;       // each moving body's velocity, as an arrow from its centre
  float velocity_scale = 0.0f;   // m of arrow per m/s; 0: chosen so the fastest body's is about 1.5 m
  bool sleeping = true;          // sleeping bodies pale and hatched
  // Busy scenes: a frame with more pairs of bodies in contact than `marked_pairs` (0: no limit)
  // draws normals and impulse arrows only for that many, the strongest, each pair's points as one
  // mark (marks.h); arrows of impulses below `faint_below` times the frame's strongest drawn faint
  // (a resting contact beside a hit; 0: none).
  int marked_pairs = 4;
  float faint_below = 0.25f;
};

// [compare] (or --vary): the scene shown as two to four panes side by side, one per value of one
// field (scene_compare.h). `key` is written as --set writes it; each value is TOML text (0.2,
// false, "projection", [0, 1, 0]).
struct CompareSpec {
  std::string origin;               // for messages: "FILE:LINE: [compare]" or "--vary ARGUMENT"
  std::string key;
  std::vector<std::string> values;  // empty: no comparison
  std::vector<std::string> labels;  // one per value
};

struct Scene {
  std::string path;
  std::vector<std::string> settings;  // the --set arguments applied over the file
  std::string title;
  double duration = 5;           // s of simulated time
  physics::WorldSettings world;
  int planar_axis = physics::kNotPlanar;  // [world] planar: the lock of every moving body that names none
  std::vector<physics::BodyDef> bodies;
  std::vector<Colour> colours;  // one per body
  std::vector<physics::JointDef> joints;  // body indices into `bodies`
  std::vector<std::string> material_names;  // the bodies' `material`s; a body's Material::kind indexes it
  CameraSetting camera;
  CameraMotion camera_motion;
  VideoSetting video;
  DrawOptions draw;
  OverlayOptions overlay;
  std::vector<CaptionCue> captions;
  std::vector<EquationCue> equations;  // [[equation]]
  PlaybackOptions playback;
  std::vector<CheckSpec> checks;  // [[check]]: what must hold
  CompareSpec compare;            // [compare]
};

// The index of the first body named `name` in scene.bodies, -1 if none is.
int find_body(const Scene& scene, std::string_view name);

}  // namespace impulse::demos
