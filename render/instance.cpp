#include "render/instance.h"

#include <algorithm>
#include <cmath>

#include "render/transforms.h"

namespace impulse::render {
namespace {

constexpr float kMinimumScale = 1e-6f;

// model = T * R * S, so its inverse transpose is R * S^-1: no general inverse needed.
Instance make_instance(const Vec3f& translation, const Quatf& rotation, const Vec3f& scale, const Colour& colour,
                       int style) {
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
  const int style = (sphere.spin_marks ? spin_marks : plain) | (sphere.sleeping ? sleeping : plain);
  return make_instance(sphere.centre, sphere.orientation, Vec3f::Constant(sphere.radius), sphere.colour, style);
}

Instance box_instance(const BoxItem& box) {
  return make_instance(box.centre, box.orientation, box.half_extents, box.colour,
                       edges | (box.sleeping ? sleeping : plain));
}

Instance cylinder_instance(const CylinderItem& cylinder) {
  const Vec3f scale(cylinder.radius, cylinder.half_height, cylinder.radius);
  const int style = (cylinder.spin_marks ? spin_marks : plain) | (cylinder.sleeping ? sleeping : plain);
  return make_instance(cylinder.centre, cylinder.orientation, scale, cylinder.colour, style);
}

Instance mesh_instance(const MeshItem& mesh) {
  return make_instance(mesh.centre, mesh.orientation, Vec3f::Ones(), mesh.colour, edges | (mesh.sleeping ? sleeping : plain));
}

Instance point_instance(const Vec3f& position, float radius, const Colour& colour) {
  return make_instance(position, Quatf::Identity(), Vec3f::Constant(radius), colour, plain);
}

}  // namespace impulse::render
