// Where the camera is at each moment: fixed, easing between [[camera.keyframe]]s, or following a
// body (keeping the offset it had at the start, smoothed over about 0.3 s so a bounce does not
// shake the view).
#pragma once
#include "demos/scene/scene.h"
#include "physics/math.h"
#include "render/draw_list.h"

#include <Eigen/Geometry>

namespace impulse::demos {

class CameraPath {
 public:
  explicit CameraPath(const Scene& scene);

  // The camera at simulated `time`; `followed_position` is the followed body's position then
  // (ignored without follow). Call with non-decreasing times: following is smoothed.
  render::Camera at(double time, const physics::Vec3& followed_position);
  int followed_body() const { return followed_body_; }  // -1 without follow
  // [camera] fit: aimed at the centre of `extent` and moved along its line of sight (its direction
  // and field of view kept) until every corner of `extent` is in view of a frame `aspect` wide to
  // 1 high, within kFitShare of its half-widths (the rest for the overlay's edges).
  void fit(const Eigen::AlignedBox3d& extent, double aspect);
  static constexpr double kFitShare = 0.85;

 private:
  render::Camera start_;
  struct Keyframe {
    double time;
    render::Camera camera;
  };
  std::vector<Keyframe> keyframes_;
  int followed_body_ = -1;
  render::Vec3f followed_start_ = render::Vec3f::Zero();
  render::Vec3f smoothed_ = render::Vec3f::Zero();
  double last_time_ = 0;
};

}  // namespace impulse::demos
