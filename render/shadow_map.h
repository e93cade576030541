// A depth texture seen from the directional light, fitted each frame around the shadow casters.
#pragma once
#include <Eigen/Core>

#include "render/draw_list.h"
#include "render/gl_objects.h"

namespace impulse::render {

struct ShadowFrustum {
  bool has_casters = false;
  Eigen::Matrix4f view_projection = Eigen::Matrix4f::Identity();
  float texel_world = 0.0f;  // metres covered by one texel
};

// An orthographic light frustum around every sphere, box, cylinder and mesh (arrows cast no shadow),
// deep enough to reach the ground below them. `towards_light` is a unit vector.
ShadowFrustum fit_shadow_frustum(const DrawList& draw_list, const Eigen::Vector3f& towards_light, int map_size);

class ShadowMap {
 public:
  explicit ShadowMap(int size);  // throws std::runtime_error if the framebuffer is incomplete

  void bind_for_drawing() const;  // binds its framebuffer, sets the viewport, clears depth
  void bind_texture(GLuint unit) const;
  int size() const { return size_; }

 private:
  int size_;
  GlTexture depth_;
  GlFramebuffer framebuffer_;
};

}  // namespace impulse::render
