// Scene files (TOML): the world, its bodies, the camera and the video, as a lecturer writes them.
// The format is described in README.md, "Scene files".
#pragma once
#include "physics/world.h"
#include "render/draw_list.h"
#include "render/video_encoder.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace impulse::demos {

// A scene file that cannot be used. what() reads "FILE:LINE: FIELD: REASON".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DrawOptions {
  bool contact_normals = true;   // an arrow along each contact's normal while it lasts
  float normal_length = 0.6f;    // m
};

struct Scene {
  std::string path;
  std::string title;
  double duration = 5;           // s of simulated time
  physics::WorldSettings world;
  std::vector<physics::BodyDef> bodies;
  std::vector<render::Colour> colours;  // one per body
  std::vector<physics::JointDef> joints;  // body indices into `bodies`
  render::Camera camera;
  render::VideoSettings video;
  DrawOptions draw;
};

Scene load_scene(const std::string& path);

}  // namespace impulse::demos
