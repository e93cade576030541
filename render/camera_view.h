// A Camera seen through a frame of a given size: the GL matrices, and where a world point lands
// in pixels (for labels of the 2D overlay and for tests).
#pragma once
#include <Eigen/Core>
#include <optional>

#include "render/draw_list.h"

namespace impulse::render {

struct CameraView {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();        // world -> camera
  Eigen::Matrix4f view_projection = Eigen::Matrix4f::Identity();
  Vec3f position = Vec3f::Zero();
  Vec3f forward = -Vec3f::UnitZ();  // unit, towards the target
  float distance_to_target = 1.0f;
  float near_distance = 0.01f;
  float far_distance = 100.0f;
  float focal_pixels = 1.0f;  // pixels per unit of (lateral offset / depth)
  int width = 1;
  int height = 1;

  // Pixel coordinates (x right, y down from the top-left corner); nullopt behind the camera.
  std::optional<Eigen::Vector2f> to_pixels(const Vec3f& world) const;
  // How many pixels one metre spans at `world`'s depth, across the view (0 behind the camera).
  float pixels_per_metre(const Vec3f& world) const;
};

// Throws std::invalid_argument if the camera's position equals its target or is not finite.
CameraView make_camera_view(const Camera& camera, int width, int height);

}  // namespace impulse::render
