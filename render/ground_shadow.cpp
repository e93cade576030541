#include "render/ground_shadow.h"

#include "render/transforms.h"

namespace impulse::render {

Instance ground_shadow_disc(const SphereItem& sphere, const Vec3f& towards_light) {
  Instance instance{};
  const Quatf facing = Quatf::FromTwoVectors(Vec3f::UnitY(), towards_light);
  Eigen::Map<Eigen::Matrix4f>(instance.model) = place(sphere.centre, facing, Vec3f(sphere.radius, 1.0f, sphere.radius));
  return instance;
}

}  // namespace impulse::render
