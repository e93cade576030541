#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include "render/gl.h"
#include "render/gl_context.h"
#include "render/gpu_mesh.h"
#include "render/instance.h"
#include "render/mesh.h"
#include "render/offscreen_target.h"
#include "render/shader.h"
#include "render/shaders.h"
#include "render/shadow_map.h"
#include "render/transforms.h"

namespace impulse::render {
namespace {

constexpr int kSphereSubdivisions = 4;
constexpr int kArrowSegments = 24;
constexpr GLuint kShadowTextureUnit = 0;
constexpr float kArrowGhostAlpha = 0.45f;  // the parts of arrows hidden behind bodies, drawn flat
constexpr float kArrowAmbientLift = 0.35f;  // arrows read as flat, uniform colours
const Vec3f kGroundColour(0.84f, 0.85f, 0.86f);

Vec3f to_vector(const Colour& colour) { return {colour.r, colour.g, colour.b}; }

struct CameraMatrices {
  Eigen::Matrix4f view_projection;
  float distance_to_target;
  float far_distance;
};

CameraMatrices camera_matrices(const Camera& camera, float aspect) {
  const Vec3f view = camera.target - camera.position;
  const float distance = view.norm();
  if (!(distance > 1e-6f) || !view.allFinite()) {
    throw std::invalid_argument("renderer: camera position must differ from its target");
  }
  // Looking straight down or up, screen-up becomes -z (away from the default camera).
  const Vec3f up = std::abs(view.y()) > 0.999f * distance ? Vec3f(-Vec3f::UnitZ()) : Vec3f(Vec3f::UnitY());
  const float near_distance = std::clamp(0.01f * distance, 0.01f, 1.0f);
  const float far_distance = 60.0f * std::max(distance, 10.0f);
  const float fov = std::clamp(camera.fov_y_degrees, 1.0f, 170.0f) * std::numbers::pi_v<float> / 180.0f;
  return {perspective(fov, aspect, near_distance, far_distance) * look_at(camera.position, camera.target, up),
          distance, far_distance};
}

// GL records errors instead of failing calls; one check per frame catches e.g. out-of-memory.
void throw_on_gl_error(const char* during) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  char message[80];
  std::snprintf(message, sizeof message, "renderer: OpenGL error 0x%04X during %s", error, during);
  throw std::runtime_error(message);
}

}  // namespace

struct Renderer::Gpu {
  // Declared first: destroyed last, after every GL object below.
  GlContext context;
  ShaderProgram lit{"lit", shaders::lit_vertex(), shaders::lit_fragment()};
  ShaderProgram ground{"ground", shaders::ground_vertex(), shaders::ground_fragment()};
  ShaderProgram shadow{"shadow", shaders::shadow_vertex(), ""};
  GpuMesh sphere_mesh{make_icosphere(kSphereSubdivisions)};
  GpuMesh cube_mesh{make_cube()};
  GpuMesh shaft_mesh{make_cylinder(kArrowSegments)};
  GpuMesh head_mesh{make_cone(kArrowSegments)};
  GpuMesh ground_mesh{make_quad()};
  OffscreenTarget target;
  std::optional<ShadowMap> shadow_map;

  // Scratch, kept to reuse their memory from frame to frame.
  std::vector<Instance> spheres, boxes, shafts, heads;

  Gpu(int width, int height, const RendererSettings& settings) : target(width, height, settings.samples) {
    if (settings.shadow_map_size > 0) shadow_map.emplace(settings.shadow_map_size);
    ground_mesh.upload({Instance{}});  // the ground shader places the quad itself
    lit.set("u_shadow_map", static_cast<int>(kShadowTextureUnit));
    ground.set("u_shadow_map", static_cast<int>(kShadowTextureUnit));
    throw_on_gl_error("setup");
  }
  ~Gpu() {
    try {
      context.make_current();  // GL objects must be deleted in their own context
    } catch (...) {
    }
  }
};

Renderer::Renderer(int width, int height, RendererSettings settings)
    : gpu_(std::make_unique<Gpu>(width, height, settings)) {}

Renderer::~Renderer() = default;

int Renderer::width() const { return gpu_->target.width(); }
int Renderer::height() const { return gpu_->target.height(); }

const Frame& Renderer::draw(const DrawList& draw_list) {
  Gpu& gpu = *gpu_;
  gpu.context.make_current();

  const float aspect = static_cast<float>(width()) / static_cast<float>(height());
  const CameraMatrices camera = camera_matrices(draw_list.camera, aspect);
  const float light_length = draw_list.towards_light.norm();
  const Vec3f towards_light = std::isfinite(light_length) && light_length > 1e-6f
                                  ? Vec3f(draw_list.towards_light / light_length)
                                  : Vec3f(DrawList{}.towards_light.normalized());

  gpu.spheres.clear();
  gpu.boxes.clear();
  gpu.shafts.clear();
  gpu.heads.clear();
  for (const SphereItem& sphere : draw_list.spheres) gpu.spheres.push_back(sphere_instance(sphere));
  for (const BoxItem& box : draw_list.boxes) gpu.boxes.push_back(box_instance(box));
  for (const ArrowItem& arrow : draw_list.arrows) {
    ArrowInstances parts;
    if (!arrow_instances(arrow, parts)) continue;
    gpu.shafts.push_back(parts.shaft);
    gpu.heads.push_back(parts.head);
  }
  gpu.sphere_mesh.upload(gpu.spheres);
  gpu.cube_mesh.upload(gpu.boxes);
  gpu.shaft_mesh.upload(gpu.shafts);
  gpu.head_mesh.upload(gpu.heads);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);

  // Shadow pass: depth of spheres and boxes as the light sees them.
  ShadowFrustum shadow;
  if (gpu.shadow_map) {
    shadow = fit_shadow_frustum(draw_list, towards_light, gpu.shadow_map->size());
  }
  if (shadow.has_casters) {
    gpu.shadow_map->bind_for_drawing();
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    gpu.shadow.use();
    gpu.shadow.set("u_view_projection", shadow.view_projection);
    gpu.sphere_mesh.draw();
    gpu.cube_mesh.draw();
    glDisable(GL_POLYGON_OFFSET_FILL);
    gpu.shadow_map->bind_texture(kShadowTextureUnit);
  }

  // Main pass.
  gpu.target.bind_for_drawing();
  const Colour& background = draw_list.background;
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);

  for (const ShaderProgram* program : {&gpu.lit, &gpu.ground}) {
    program->set("u_view_projection", camera.view_projection);
    program->set("u_light_direction", towards_light);
    program->set("u_camera_position", draw_list.camera.position);
    program->set("u_light_view_projection", shadow.view_projection);
    program->set("u_shadows_enabled", shadow.has_casters ? 1 : 0);
    program->set("u_shadow_texel_world", shadow.texel_world);
  }

  if (draw_list.ground) {
    const Vec3f centre(draw_list.camera.target.x(), draw_list.ground_height, draw_list.camera.target.z());
    gpu.ground.use();
    gpu.ground.set("u_ground_centre", centre);
    gpu.ground.set("u_ground_half_size", 0.7f * camera.far_distance);
    gpu.ground.set("u_background", to_vector(background));
    gpu.ground.set("u_ground_colour", kGroundColour);
    gpu.ground.set("u_fog_start", 2.5f * camera.distance_to_target);
    gpu.ground.set("u_fog_end", 0.25f * camera.far_distance);
    glDisable(GL_CULL_FACE);  // visible from below too
    gpu.ground_mesh.draw();
    glEnable(GL_CULL_FACE);
  }

  gpu.lit.use();
  gpu.lit.set("u_alpha", 1.0f);
  gpu.lit.set("u_ambient_lift", 0.0f);
  gpu.sphere_mesh.draw();
  gpu.cube_mesh.draw();

  // Arrows: first a faint ghost of the parts hidden behind bodies, then the visible parts.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  gpu.lit.set("u_alpha", kArrowGhostAlpha);
  gpu.lit.set("u_ambient_lift", 1.0f);
  gpu.shaft_mesh.draw();
  gpu.head_mesh.draw();
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  gpu.lit.set("u_alpha", 1.0f);
  gpu.lit.set("u_ambient_lift", kArrowAmbientLift);
  gpu.shaft_mesh.draw();
  gpu.head_mesh.draw();

  gpu.target.resolve_into(frame_);
  throw_on_gl_error("draw");
  return frame_;
}

}  // namespace impulse::render
