#include "demos/film/body_boxes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <span>

namespace impulse::demos {
namespace {

// A sphere's outline is a little wider than its radius at its centre's depth, off the view's axis.
constexpr float kSphereWiden = 1.05f;

std::optional<render::ScreenBox> sphere_box(const physics::Vec3& centre, double radius, const render::CameraView& view) {
  const render::Vec3f at = centre.cast<float>();
  const auto pixel = view.to_pixels(at);
  const float reach = float(radius) * view.pixels_per_metre(at) * kSphereWiden;
  if (!pixel || !(reach > 0)) return std::nullopt;
  return render::ScreenBox{pixel->x() - reach, pixel->y() - reach, 2 * reach, 2 * reach};
}

// The box round `corners` (in the body's frame) where the pose puts them.
std::optional<render::ScreenBox> corners_box(const BodyPose& pose, std::span<const physics::Vec3> corners,
                                             const render::CameraView& view) {
  if (corners.empty()) return std::nullopt;
  Eigen::Vector2f low = Eigen::Vector2f::Constant(1e30f), high = Eigen::Vector2f::Constant(-1e30f);
  for (const physics::Vec3& corner : corners) {
    const physics::Vec3 point = pose.position + pose.orientation * corner;
    const auto pixel = view.to_pixels(point.cast<float>());
    if (!pixel) return std::nullopt;  // partly behind the camera: no box worth having
    low = low.cwiseMin(*pixel);
    high = high.cwiseMax(*pixel);
  }
  return render::ScreenBox{low.x(), low.y(), high.x() - low.x(), high.y() - low.y()};
}

std::optional<render::ScreenBox> box_box(const BodyPose& pose, const physics::Vec3& half, const render::CameraView& view) {
  std::array<physics::Vec3, 8> corners;
  for (int corner = 0; corner < 8; ++corner) corners[corner] = physics::box_corner(half, corner);
  return corners_box(pose, corners, view);
}

// The box cut to a frame's size beyond each edge of the frame: a body close to the camera
// projects to thousands of frames' width, and what matters is only that it covers the frame.
render::ScreenBox within_reach(const render::ScreenBox& box, const render::CameraView& view) {
  const float w = float(view.width), h = float(view.height);
  const float x0 = std::max(box.x, -w), y0 = std::max(box.y, -h);
  const float x1 = std::min(box.right(), 2 * w), y1 = std::min(box.bottom(), 2 * h);
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

void add_body_boxes(const std::vector<physics::Body>& bodies, const std::vector<BodyPose>& poses,
                    const render::CameraView& view, std::vector<render::OverlayBody>& out) {
  for (size_t i = 0; i < bodies.size() && i < poses.size(); ++i) {
    const physics::Body& body = bodies[i];
    std::optional<render::ScreenBox> box;
    const physics::Shape& shape = body.shape;
    switch (shape.type) {
      case physics::ShapeType::sphere: box = sphere_box(poses[i].position, shape.radius, view); break;
      case physics::ShapeType::box: box = box_box(poses[i], shape.half_extents, view); break;
      // The box in the body's frame that holds it (its axis along y).
      case physics::ShapeType::cylinder:
        box = box_box(poses[i], physics::Vec3(shape.radius, shape.half_height, shape.radius), view);
        break;
      case physics::ShapeType::capsule:
        box = box_box(poses[i], physics::Vec3(shape.radius, shape.half_height + shape.radius, shape.radius), view);
        break;
      case physics::ShapeType::hull:
        if (shape.hull()) box = corners_box(poses[i], shape.hull()->corners, view);
        break;
      case physics::ShapeType::mesh:  // a surface, as a plane: what lies on it is what the eye follows
      case physics::ShapeType::plane: break;
    }
    if (!box || !(box->right() > 0 && box->bottom() > 0 && box->x < float(view.width) && box->y < float(view.height))) continue;
    out.push_back({0, body.name, within_reach(*box, view), !body.is_static()});
  }
}

BodyPaths::BodyPaths(int width, int height)
    : cell_(std::max(2.0f, float(std::min(width, height)) / 48)),
      columns_(std::max(1, int(std::ceil(width / cell_)))),
      rows_(std::max(1, int(std::ceil(height / cell_)))),
      covered_(size_t(columns_) * rows_, 0) {}

void BodyPaths::add(const render::ScreenBox& box) {
  // Boxes are cut to a frame beyond each edge (add_body_boxes), so these stay small numbers.
  const int i0 = std::clamp(int(std::floor(box.x / cell_)), 0, columns_), i1 = std::clamp(int(std::ceil(box.right() / cell_)), 0, columns_);
  const int j0 = std::clamp(int(std::floor(box.y / cell_)), 0, rows_), j1 = std::clamp(int(std::ceil(box.bottom() / cell_)), 0, rows_);
  for (int j = j0; j < j1; ++j) std::fill(covered_.begin() + size_t(j) * columns_ + i0, covered_.begin() + size_t(j) * columns_ + i1, 1);
}

std::vector<render::ScreenBox> BodyPaths::boxes() const {
  std::vector<render::ScreenBox> boxes;
  std::map<std::pair<int, int>, size_t> open;  // the runs (first, end cell) of the row above, by box
  for (int j = 0; j < rows_; ++j) {
    std::map<std::pair<int, int>, size_t> continued;
    for (int i = 0; i < columns_;) {
      if (!covered_[size_t(j) * columns_ + i]) {
        ++i;
        continue;
      }
      const int first = i;
      while (i < columns_ && covered_[size_t(j) * columns_ + i]) ++i;
      const auto above = open.find({first, i});
      if (above != open.end()) {
        boxes[above->second].h += cell_;
        continued[{first, i}] = above->second;
      } else {
        continued[{first, i}] = boxes.size();
        boxes.push_back({first * cell_, j * cell_, (i - first) * cell_, cell_});
      }
    }
    open = std::move(continued);
  }
  return boxes;
}

}  // namespace impulse::demos
