// What one frame shows, as plain data. The demos layer fills it from the world and the step's
// records; the renderer only draws it. render/ knows nothing of physics/.
#pragma once
#include <Eigen/Geometry>
#include <vector>

namespace impulse::render {

using Vec3f = Eigen::Vector3f;
using Quatf = Eigen::Quaternionf;

struct Colour { float r = 0.8f, g = 0.8f, b = 0.8f; };

// spin_marks darkens alternate octants of the sphere so its rotation is visible.
struct SphereItem { Vec3f centre; float radius = 0.5f; Quatf orientation = Quatf::Identity(); Colour colour; bool spin_marks = true; };
struct BoxItem { Vec3f centre; Vec3f half_extents{0.5f, 0.5f, 0.5f}; Quatf orientation = Quatf::Identity(); Colour colour; };
// An arrow from `origin` along `direction` (its length is the arrow's length in metres).
struct ArrowItem { Vec3f origin; Vec3f direction; Colour colour; };

struct Camera {
  Vec3f position{0.0f, 3.0f, 10.0f};
  Vec3f target{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
};

struct DrawList {
  Camera camera;
  Colour background{0.92f, 0.94f, 0.97f};
  Vec3f towards_light{-0.45f, 1.0f, 0.6f};  // direction to the one directional light (any length)
  bool ground = true;         // the plane y = ground_height
  float ground_height = 0.0f;
  std::vector<SphereItem> spheres;
  std::vector<BoxItem> boxes;
  std::vector<ArrowItem> arrows;
};

}  // namespace impulse::render
