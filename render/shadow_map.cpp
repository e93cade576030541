#include "render/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/transforms.h"

namespace impulse::render {

ShadowFrustum fit_shadow_frustum(const DrawList& draw_list, const Eigen::Vector3f& towards_light, int map_size) {
  Eigen::AlignedBox3f bounds;
  for (const SphereItem& sphere : draw_list.spheres) {
    bounds.extend(sphere.centre - Vec3f::Constant(sphere.radius));
    bounds.extend(sphere.centre + Vec3f::Constant(sphere.radius));
  }
  for (const BoxItem& box : draw_list.boxes) {
    const float reach = box.half_extents.norm();
    bounds.extend(box.centre - Vec3f::Constant(reach));
    bounds.extend(box.centre + Vec3f::Constant(reach));
  }
  for (const CylinderItem& cylinder : draw_list.cylinders) {
    const float reach = std::hypot(cylinder.radius, cylinder.half_height);  // to a rim
    bounds.extend(cylinder.centre - Vec3f::Constant(reach));
    bounds.extend(cylinder.centre + Vec3f::Constant(reach));
  }
  for (const MeshItem& mesh : draw_list.meshes) {
    if (!mesh.triangles) continue;
    const Quatf turn = mesh.orientation.normalized();
    for (const Vec3f& corner : *mesh.triangles) bounds.extend(mesh.centre + turn * corner);
  }
  ShadowFrustum frustum;
  if (bounds.isEmpty() || !bounds.sizes().allFinite()) return frustum;

  const Vec3f centre = bounds.center();
  const float radius = 0.5f * bounds.sizes().norm() + 0.1f;
  // Far enough behind the casters to reach the ground under them along the light.
  const float height_above_ground = std::max(centre.y() - draw_list.ground_height, 0.0f);
  const float ground_reach = height_above_ground / std::max(towards_light.y(), 0.1f);
  const Vec3f eye = centre + towards_light * (radius + 1.0f);
  const Vec3f up = std::abs(towards_light.y()) > 0.99f ? Vec3f::UnitZ() : Vec3f::UnitY();

  frustum.has_casters = true;
  frustum.view_projection = orthographic(radius, radius, 0.0f, 2.0f * radius + ground_reach + 2.0f) *
                            look_at(eye, centre, up);
  frustum.texel_world = 2.0f * radius / static_cast<float>(map_size);
  return frustum;
}

ShadowMap::ShadowMap(int size) : size_(size) {
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D, 0);

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("OpenGL: shadow-map framebuffer is incomplete");
}

void ShadowMap::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, size_, size_);
  glClear(GL_DEPTH_BUFFER_BIT);
}

void ShadowMap::bind_texture(GLuint unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, depth_.id());
}

}  // namespace impulse::render
