#include "demos/film/camera_path.h"

#include "demos/film/render_types.h"

#include <cmath>

namespace impulse::demos {
namespace {

constexpr double kFollowSmoothing = 0.3;  // s: time constant of the followed position

render::Camera blend(const render::Camera& a, const render::Camera& b, float weight) {
  render::Camera camera;
  camera.position = a.position + (b.position - a.position) * weight;
  camera.target = a.target + (b.target - a.target) * weight;
  camera.fov_y_degrees = a.fov_y_degrees + (b.fov_y_degrees - a.fov_y_degrees) * weight;
  return camera;
}

}  // namespace

CameraPath::CameraPath(const Scene& scene) : start_(to_render(scene.camera)) {
  for (const CameraKeyframe& keyframe : scene.camera_motion.keyframes)
    keyframes_.push_back({keyframe.time, to_render(keyframe.camera)});
  if (!scene.camera_motion.follow.empty()) followed_body_ = find_body(scene, scene.camera_motion.follow);
  if (followed_body_ >= 0) {
    followed_start_ = scene.bodies[followed_body_].position.cast<float>();
    smoothed_ = followed_start_;
  }
}

void CameraPath::fit(const Eigen::AlignedBox3d& extent, double aspect) {
  if (extent.isEmpty()) return;
  const Eigen::Vector3d eye = start_.position.cast<double>(), target = start_.target.cast<double>();
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d side = std::abs(forward.y()) > 0.999 ? Eigen::Vector3d::UnitX() : forward.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d up = side.cross(forward);
  const double ty = std::tan(start_.fov_y_degrees * M_PI / 360) * kFitShare, tx = ty * aspect;
  // A corner q from the centre, at distance D along the line of sight: in view where
  // |q . side| <= (D + q . forward) tx and |q . up| <= (D + q . forward) ty.
  const Eigen::Vector3d centre = extent.center();
  double distance = 0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d q = extent.corner(Eigen::AlignedBox3d::CornerType(k)) - centre;
    distance = std::max({distance, std::abs(q.dot(side)) / tx - q.dot(forward), std::abs(q.dot(up)) / ty - q.dot(forward)});
  }
  distance = std::max(distance, 0.5 * extent.diagonal().norm() + 0.1);  // in front of all it frames
  start_.target = centre.cast<float>();
  start_.position = (centre - distance * forward).cast<float>();
}

render::Camera CameraPath::at(double time, const physics::Vec3& followed_position) {
  if (followed_body_ >= 0) {
    const double elapsed = std::max(0.0, time - last_time_);
    last_time_ = time;
    const float weight = float(1 - std::exp(-elapsed / kFollowSmoothing));
    smoothed_ += (followed_position.cast<float>() - smoothed_) * weight;
    render::Camera camera = start_;
    const render::Vec3f moved = smoothed_ - followed_start_;
    camera.position += moved;
    camera.target += moved;
    return camera;
  }
  render::Camera from = start_;
  double from_time = 0;
  for (const Keyframe& keyframe : keyframes_) {
    if (time < keyframe.time) {
      const double x = (time - from_time) / (keyframe.time - from_time);
      return blend(from, keyframe.camera, float(x * x * (3 - 2 * x)));  // ease in and out
    }
    from = keyframe.camera;
    from_time = keyframe.time;
  }
  return from;
}

}  // namespace impulse::demos
