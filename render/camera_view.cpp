#include "render/camera_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "render/transforms.h"

namespace impulse::render {

CameraView make_camera_view(const Camera& camera, int width, int height) {
  const Vec3f to_target = camera.target - camera.position;
  const float distance = to_target.norm();
  if (!(distance > 1e-6f) || !to_target.allFinite()) {
    throw std::invalid_argument("renderer: camera position must differ from its target");
  }
  CameraView view;
  view.width = width;
  view.height = height;
  view.position = camera.position;
  view.forward = to_target / distance;
  // Looking straight down or up, screen-up becomes -z (away from the default camera).
  const Vec3f up = std::abs(view.forward.y()) > 0.999f ? Vec3f(-Vec3f::UnitZ()) : Vec3f(Vec3f::UnitY());
  view.distance_to_target = distance;
  view.near_distance = std::clamp(0.01f * distance, 0.01f, 1.0f);
  view.far_distance = 60.0f * std::max(distance, 10.0f);
  const float fov = std::clamp(camera.fov_y_degrees, 1.0f, 170.0f) * std::numbers::pi_v<float> / 180.0f;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  view.view = look_at(camera.position, camera.target, up);
  view.view_projection = perspective(fov, aspect, view.near_distance, view.far_distance) * view.view;
  view.focal_pixels = 0.5f * static_cast<float>(height) / std::tan(fov / 2.0f);
  return view;
}

std::optional<Eigen::Vector2f> CameraView::to_pixels(const Vec3f& world) const {
  const Eigen::Vector4f clip = view_projection * world.homogeneous();
  if (!(clip.w() > 1e-6f)) return std::nullopt;
  const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
  return Eigen::Vector2f((ndc.x() + 1.0f) * 0.5f * static_cast<float>(width),
                         (1.0f - ndc.y()) * 0.5f * static_cast<float>(height));
}

float CameraView::pixels_per_metre(const Vec3f& world) const {
  const float depth = (world - position).dot(forward);
  return depth > 1e-6f ? focal_pixels / depth : 0.0f;
}

}  // namespace impulse::render
