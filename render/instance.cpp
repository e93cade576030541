#include "render/instance.h"

#include <algorithm>
#include <cmath>

#include "render/transforms.h"

namespace impulse::render {
namespace {

constexpr float kMinimumScale = 1e-6f;

// model = T * R * S, so its inverse transpose is R * S^-1: no general inverse needed.
Instance make_instance(const Vec3f& translation, const Quatf& rotation, const Vec3f& scale, const Colour& colour,
                       InstanceStyle style) {
  const Vec3f safe_scale = scale.cwiseMax(kMinimumScale);
  Instance instance{};
  Eigen::Map<Eigen::Matrix4f>(instance.model) = place(translation, rotation, safe_scale);
  Eigen::Map<Eigen::Matrix3f>(instance.normal_matrix) =
      rotation.normalized().toRotationMatrix() * safe_scale.cwiseInverse().asDiagonal();
  instance.colour[0] = colour.r;
  instance.colour[1] = colour.g;
  instance.colour[2] = colour.b;
  instance.style = static_cast<float>(style);
  return instance;
}

}  // namespace

Instance sphere_instance(const SphereItem& sphere) {
  const InstanceStyle style = sphere.spin_marks ? InstanceStyle::spin_marks : InstanceStyle::plain;
  return make_instance(sphere.centre, sphere.orientation, Vec3f::Constant(sphere.radius), sphere.colour, style);
}

Instance box_instance(const BoxItem& box) {
  return make_instance(box.centre, box.orientation, box.half_extents, box.colour, InstanceStyle::edges);
}

bool arrow_instances(const ArrowItem& arrow, ArrowInstances& out) {
  const float length = arrow.direction.norm();
  if (!(length > 1e-5f)) return false;  // also rejects NaN
  const Vec3f axis = arrow.direction / length;
  const Quatf rotation = Quatf::FromTwoVectors(Vec3f::UnitY(), axis);

  const float head_length = std::min(0.35f * length, 0.3f);
  const float head_radius = 0.38f * head_length;
  const float shaft_radius = 0.42f * head_radius;
  const float shaft_length = length - head_length;

  out.shaft = make_instance(arrow.origin, rotation, Vec3f(shaft_radius, shaft_length, shaft_radius), arrow.colour,
                            InstanceStyle::plain);
  out.head = make_instance(arrow.origin + axis * shaft_length, rotation,
                           Vec3f(head_radius, head_length, head_radius), arrow.colour, InstanceStyle::plain);
  return true;
}

}  // namespace impulse::render
