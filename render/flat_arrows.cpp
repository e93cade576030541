#include "render/flat_arrows.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace impulse::render {
namespace {

constexpr float kMinShaftWidthPixels = 2.5f;
constexpr float kMinHeadWidthPixels = 10.0f;
constexpr float kLayerOffset = 0.002f;  // of the distance to the eye, towards it, per layer

// A corner of a triangle and its values of FlatVertex::outline.
struct Corner {
  Vec3f position;
  std::array<float, 4> outline;
};

void add(std::vector<FlatVertex>& triangles, const Colour& colour, const Corner& a, const Corner& b, const Corner& c) {
  for (const Corner* corner : {&a, &b, &c}) {
    const Corner& k = *corner;
    triangles.push_back({{k.position.x(), k.position.y(), k.position.z()},
                         {colour.r, colour.g, colour.b},
                         {k.outline[0], k.outline[1], k.outline[2], k.outline[3]}});
  }
}

// A strip from `from` to `to`, `side` either side of its line, as two triangles; its outline is
// its two sides, and its ends where said (the shaft's end under the head is not).
void add_strip(std::vector<FlatVertex>& triangles, const Colour& colour, const Vec3f& from, const Vec3f& to,
               const Vec3f& side, bool outlined_to) {
  const float end = outlined_to ? 0.0f : 2.0f;  // the `to` end's value (across: 1 - along)
  const Corner from_left{from - side, {0, 2, 0, outlined_to ? 1.0f : 2.0f}};
  const Corner to_left{to - side, {0, 2, 1, end}};
  const Corner to_right{to + side, {2, 0, 1, end}};
  const Corner from_right{from + side, {2, 0, 0, outlined_to ? 1.0f : 2.0f}};
  add(triangles, colour, from_left, to_left, to_right);
  add(triangles, colour, from_left, to_right, from_right);
}

}  // namespace

namespace {

// An arrow's corners as drawn: the shaft from `origin` to `head_base`, `shaft_side` either side of
// its line, and the head from `head_base` (`head_side` either side) to `tip`.
struct ArrowShape {
  Vec3f origin, head_base, tip, shaft_side, head_side;
};

std::optional<ArrowShape> arrow_shape(const ArrowItem& arrow, const CameraView& camera) {
  const float length = arrow.direction.norm();
  if (!(length > 1e-5f) || !arrow.origin.allFinite()) return std::nullopt;
  const Vec3f axis = arrow.direction / length;
  const Vec3f middle = arrow.origin + 0.5f * arrow.direction;
  const float pixels_per_metre = camera.pixels_per_metre(middle);
  if (!(pixels_per_metre > 0.0f)) return std::nullopt;

  // Across the arrow, in the plane facing the camera; any perpendicular if it points at the eye.
  Vec3f side = axis.cross(camera.position - middle);
  if (side.squaredNorm() < 1e-12f) side = axis.unitOrthogonal();
  side.normalize();

  const float metres_per_pixel = 1.0f / pixels_per_metre;
  const float head_length = std::min(0.35f * length, std::max(0.3f, 1.2f * kMinHeadWidthPixels * metres_per_pixel));
  const float head_half_width = std::max(0.38f * head_length, 0.5f * kMinHeadWidthPixels * metres_per_pixel);
  const float shaft_half_width = std::max(0.3f * head_half_width, 0.5f * kMinShaftWidthPixels * metres_per_pixel);

  // Layers: each moves the arrow a little towards the eye, without changing its size on screen.
  const Vec3f to_eye = camera.position - middle;
  const Vec3f lift = to_eye * (kLayerOffset * static_cast<float>(std::clamp(arrow.layer, 0, 10)));
  const Vec3f origin = arrow.origin + lift;
  return ArrowShape{origin, origin + axis * (length - std::min(head_length, length)), origin + arrow.direction,
                    side * shaft_half_width, side * head_half_width};
}

}  // namespace

void append_flat_arrow(const ArrowItem& arrow, const CameraView& camera, std::vector<FlatVertex>& triangles) {
  const std::optional<ArrowShape> shape = arrow_shape(arrow, camera);
  if (!shape) return;
  const auto& [origin, head_base, tip, shaft_side, head_side] = *shape;
  const Colour& c = arrow.colour;
  add_strip(triangles, c, origin, head_base, shaft_side, false);  // its end under the head is inside the arrow
  add(triangles, c, {head_base - head_side, {1, 0, 0, 2}}, {tip, {0, 1, 0, 2}}, {head_base + head_side, {0, 0, 1, 2}});
}

void append_flat_arrow_outline(const ArrowItem& arrow, const CameraView& camera, std::vector<ScreenSegment>& outline) {
  const std::optional<ArrowShape> shape = arrow_shape(arrow, camera);
  if (!shape) return;
  const auto& [origin, head_base, tip, shaft_side, head_side] = *shape;
  const Vec3f corners[][2] = {{origin, tip},
                              {origin - shaft_side, head_base - shaft_side},
                              {origin + shaft_side, head_base + shaft_side},
                              {head_base - head_side, head_base + head_side},
                              {head_base - head_side, tip},
                              {head_base + head_side, tip}};
  for (const auto& [from, to] : corners) {
    const auto a = camera.to_pixels(from), b = camera.to_pixels(to);
    if (a && b) outline.push_back({*a, *b});
  }
}

void append_flat_line(const LineItem& line, const CameraView& camera, std::vector<FlatVertex>& triangles) {
  const Vec3f along = line.to - line.from;
  if (!(along.norm() > 1e-6f) || !line.from.allFinite()) return;
  const Vec3f middle = line.from + 0.5f * along;
  const float pixels_per_metre = camera.pixels_per_metre(middle);
  if (!(pixels_per_metre > 0.0f)) return;
  Vec3f side = along.cross(camera.position - middle);
  if (side.squaredNorm() < 1e-12f) side = along.unitOrthogonal();
  side = side.normalized() * (0.5f * std::max(line.width_pixels, 1.0f) / pixels_per_metre);
  const Colour& c = line.colour;
  add_strip(triangles, c, line.from, line.to, side, true);
}

}  // namespace impulse::render
