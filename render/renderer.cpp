#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "render/camera_view.h"
#include "render/gl.h"
#include "render/gl_context.h"
#include "render/flat_arrows.h"
#include "render/flat_mesh.h"
#include "render/gpu_mesh.h"
#include "render/ground_shadow.h"
#include "render/instance.h"
#include "render/level_of_detail.h"
#include "render/mesh.h"
#include "render/offscreen_target.h"
#include "render/shader.h"
#include "render/shaders.h"
#include "render/shadow_map.h"

namespace impulse::render {
namespace {

constexpr GLuint kShadowTextureUnit = 0;
constexpr float kOutlineTolerancePixels = 0.25f;  // how far a tessellated outline may stray
constexpr float kArrowGhostAlpha = 0.55f;  // the parts of arrows hidden behind bodies, drawn flat
const Vec3f kGroundColour(0.84f, 0.85f, 0.86f);

// Which mesh the lit program draws (u_mesh) and which caster the ground shadow's (u_caster), as
// shaders.cpp numbers them: each has its own outlines.
enum class LitMesh { box = 0, sphere = 1, cylinder = 2, face = 3 };
enum class ShadowCaster { box = 0, disc = 1, cylinder = 2, face = 3 };

// A flat mesh's GPU copy is kept while some draw among the last this many drew it: a film's panes
// share one renderer, and a body may leave the view for a while.
constexpr uint64_t kMeshDrawsKept = 64;

Vec3f to_vector(const Colour& colour) { return {colour.r, colour.g, colour.b}; }

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

// What the kept sky and ground were drawn for.
struct BackgroundKey {
  Camera camera;
  Colour background;
  bool ground;
  float ground_height;
  Vec3f towards_light;
  Eigen::Vector2f subpixel_offset;

  bool operator==(const BackgroundKey& other) const {
    auto same = [](const Colour& a, const Colour& b) { return a.r == b.r && a.g == b.g && a.b == b.b; };
    return camera.position == other.camera.position && camera.target == other.camera.target &&
           camera.fov_y_degrees == other.camera.fov_y_degrees && same(background, other.background) &&
           ground == other.ground && ground_height == other.ground_height && towards_light == other.towards_light &&
           subpixel_offset == other.subpixel_offset;
  }
};

// Where the multisamples of a pixel lie, relative to its centre, as the impostor shader needs.
std::vector<float> sample_offsets(const OffscreenTarget& target) {
  std::vector<float> offsets;
  target.bind_for_drawing();
  for (int i = 0; i < std::max(target.samples(), 1); ++i) {
    GLfloat position[2] = {0.5f, 0.5f};
    if (target.samples() > 0) glGetMultisamplefv(GL_SAMPLE_POSITION, static_cast<GLuint>(i), position);
    offsets.push_back(position[0] - 0.5f);
    offsets.push_back(position[1] - 0.5f);
  }
  return offsets;
}

// One icosphere per subdivision level 0 .. N-1.
template <size_t N>
std::array<GpuMesh, N> make_sphere_levels() {
  return []<size_t... Level>(std::index_sequence<Level...>) {
    return std::array<GpuMesh, N>{GpuMesh(make_icosphere(static_cast<int>(Level)))...};
  }(std::make_index_sequence<N>{});
}

// The GPU copy of one MeshItem::triangles, and this draw's items of it.
struct KeptMesh {
  explicit KeptMesh(std::shared_ptr<const std::vector<Vec3f>> corners)
      : triangles(std::move(corners)), mesh(make_flat_mesh(*triangles)) {}
  std::shared_ptr<const std::vector<Vec3f>> triangles;  // held: its address is the key
  GpuMesh mesh;
  std::vector<Instance> instances;
  uint64_t last_draw = 0;
};

}  // namespace

struct Renderer::Gpu {
  // Declared first: destroyed last, after every GL object below.
  GlContext context;
  RendererSettings settings;
  bool shadow_map_on = settings.shadows == ShadowMethod::shadow_map && settings.shadow_map_size > 0;
  bool edges_on = settings.antialiasing == Antialiasing::edges;
  int samples = settings.antialiasing == Antialiasing::msaa ? settings.samples : 0;
  ShaderProgram lit{"lit", shaders::lit_vertex(), shaders::lit_fragment(shadow_map_on, edges_on)};
  ShaderProgram impostor{"impostor", shaders::impostor_vertex(), shaders::impostor_fragment(shadow_map_on, edges_on)};
  ShaderProgram ground{"ground", shaders::ground_vertex(), shaders::ground_fragment(shadow_map_on, false, edges_on)};
  ShaderProgram ground_shadow{"ground shadow", shaders::ground_shadow_vertex(),
                              shaders::ground_fragment(false, true, edges_on)};
  ShaderProgram depth_only{"shadow", shaders::shadow_vertex(), ""};
  ShaderProgram impostor_shadow{"impostor shadow", shaders::impostor_shadow_vertex(),
                                shaders::impostor_shadow_fragment()};
  std::array<GpuMesh, kMaxSphereLevel + 1> sphere_levels = make_sphere_levels<kMaxSphereLevel + 1>();
  ShaderProgram flat{"flat", shaders::flat_vertex(), shaders::flat_fragment(edges_on)};
  FlatMesh arrow_mesh;
  GpuMesh cube_mesh{make_cube()};
  GpuMesh cylinder_mesh{make_cylinder(kCylinderSegments)};
  GpuMesh shadow_discs{make_quad()};  // each around a sphere's great disc (ground_shadow.h)
  GpuMesh sphere_quads{make_quad()};
  GpuMesh point_quads{make_quad()};
  GpuMesh ground_mesh{make_quad()};
  std::unordered_map<const std::vector<Vec3f>*, KeptMesh> meshes;  // by MeshItem::triangles
  std::vector<KeptMesh*> meshes_drawn;  // this draw's, in the draw list's order: the same bytes every run
  uint64_t draws = 0;
  OffscreenTarget target;
  std::optional<ShadowMap> shadow_map;
  // Sky and ground depend only on the camera and the light unless the shadow map falls on the
  // ground: then they are kept here and copied in (cheaper than clearing), redrawn on a change.
  std::optional<OffscreenTarget> background;
  std::optional<BackgroundKey> background_key;
  Eigen::Vector2f subpixel_offset = Eigen::Vector2f::Zero();  // pixels, x right, y down

  // Scratch, kept to reuse their memory from frame to frame.
  std::array<std::vector<Instance>, kMaxSphereLevel + 1> spheres_by_level;
  std::vector<Instance> spheres, boxes, cylinders, points, discs;
  std::vector<FlatVertex> arrows;

  Gpu(int width, int height, const RendererSettings& renderer_settings)
      : settings(renderer_settings), target(width, height, samples, edges_on) {
    if (!shadow_map_on) background.emplace(width, height, samples);
    if (shadow_map_on) {
      shadow_map.emplace(settings.shadow_map_size);
      for (const ShaderProgram* program : {&lit, &impostor, &ground}) {
        program->set("u_shadow_map", static_cast<int>(kShadowTextureUnit));
      }
    }
    ground_mesh.upload({Instance{}});  // the ground shader places the quad itself
    const std::vector<float> offsets = sample_offsets(target);
    for (const ShaderProgram* program : {&impostor, &ground_shadow}) {
      program->use();
      glUniform2fv(glGetUniformLocation(program->id(), "u_sample_offsets"), static_cast<GLsizei>(offsets.size() / 2),
                   offsets.data());
      program->set("u_sample_count", static_cast<int>(offsets.size() / 2));
    }
    throw_on_gl_error("setup");
  }
  ~Gpu() {
    try {
      context.make_current();  // GL objects must be deleted in their own context
    } catch (...) {
    }
  }

  void collect(const DrawList& draw_list, const CameraView& camera, const Vec3f& towards_light);
  void draw_meshes() const {
    for (const KeptMesh* kept : meshes_drawn) kept->mesh.draw();
  }
  void draw_shadows(const ShadowFrustum& shadow, const Vec3f& towards_light);
  void draw_bodies();
  void draw_marks();  // arrows and points
  void draw_ground(const DrawList& draw_list, const CameraView& camera);
  void clear(const Colour& background) const;
  void prepare_background(const DrawList& draw_list, const CameraView& camera, const Vec3f& towards_light);
  void draw_ground_shadows(const DrawList& draw_list);
};

// Sorts every item into the instance lists of the meshes that draw it, and uploads them.
void Renderer::Gpu::collect(const DrawList& draw_list, const CameraView& camera, const Vec3f& towards_light) {
  for (auto& list : spheres_by_level) list.clear();
  spheres.clear();
  boxes.clear();
  cylinders.clear();
  points.clear();
  arrows.clear();
  discs.clear();

  const bool ground_shadows = settings.shadows == ShadowMethod::ground && draw_list.ground;
  for (const SphereItem& sphere : draw_list.spheres) {
    spheres.push_back(sphere_instance(sphere));
    if (ground_shadows) discs.push_back(ground_shadow_disc(sphere, towards_light));
    if (settings.spheres == SphereMethod::tessellated) {
      const float radius_pixels = sphere.radius * camera.pixels_per_metre(sphere.centre);
      spheres_by_level[sphere_level(radius_pixels, kOutlineTolerancePixels)].push_back(spheres.back());
    }
  }
  for (const BoxItem& box : draw_list.boxes) boxes.push_back(box_instance(box));
  for (const CylinderItem& cylinder : draw_list.cylinders) cylinders.push_back(cylinder_instance(cylinder));
  ++draws;
  meshes_drawn.clear();
  for (auto& [corners, kept] : meshes) kept.instances.clear();
  for (const MeshItem& mesh : draw_list.meshes) {
    if (!mesh.triangles || mesh.triangles->size() < 3) continue;
    KeptMesh& kept = meshes.try_emplace(mesh.triangles.get(), mesh.triangles).first->second;
    if (kept.instances.empty()) meshes_drawn.push_back(&kept);
    kept.instances.push_back(mesh_instance(mesh));
    kept.last_draw = draws;
  }
  std::erase_if(meshes, [&](const auto& entry) { return draws - entry.second.last_draw >= kMeshDrawsKept; });
  for (const LineItem& line : draw_list.lines) append_flat_line(line, camera, arrows);
  for (const ArrowItem& arrow : draw_list.arrows) append_flat_arrow(arrow, camera, arrows);
  for (const PointItem& point : draw_list.points) {
    const float pixels_per_metre = camera.pixels_per_metre(point.position);
    if (!(pixels_per_metre > 0.0f) || !(point.radius_pixels > 0.0f)) continue;
    points.push_back(point_instance(point.position, std::min(point.radius_pixels / pixels_per_metre, point.largest_radius), point.colour));
  }

  sphere_quads.upload(spheres);
  for (int level = 0; level <= kMaxSphereLevel; ++level) sphere_levels[level].upload(spheres_by_level[level]);
  cube_mesh.upload(boxes);
  cylinder_mesh.upload(cylinders);
  for (KeptMesh* kept : meshes_drawn) kept->mesh.upload(kept->instances);
  arrow_mesh.upload(arrows);
  point_quads.upload(points);
  shadow_discs.upload(discs);
}

// Depth of spheres (always ray-cast: exact and cheap), boxes, cylinders and meshes as the light
// sees them.
void Renderer::Gpu::draw_shadows(const ShadowFrustum& shadow, const Vec3f& towards_light) {
  shadow_map->bind_for_drawing();
  glDisable(GL_CULL_FACE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  depth_only.use();
  depth_only.set("u_view_projection", shadow.view_projection);
  cube_mesh.draw();
  cylinder_mesh.draw();
  draw_meshes();
  glDisable(GL_POLYGON_OFFSET_FILL);
  impostor_shadow.use();
  impostor_shadow.set("u_view_projection", shadow.view_projection);
  impostor_shadow.set("u_light_direction", towards_light);
  sphere_quads.draw();
  shadow_map->bind_texture(kShadowTextureUnit);
}

void Renderer::Gpu::draw_bodies() {
  glEnable(GL_CULL_FACE);
  lit.use();
  lit.set("u_alpha", 1.0f);
  lit.set("u_ambient_lift", 0.0f);
  lit.set("u_mesh", int(LitMesh::box));
  cube_mesh.draw();
  lit.set("u_mesh", int(LitMesh::cylinder));
  cylinder_mesh.draw();
  lit.set("u_mesh", int(LitMesh::face));
  draw_meshes();
  if (settings.spheres == SphereMethod::tessellated) {
    lit.set("u_mesh", int(LitMesh::sphere));
    for (const GpuMesh& level : sphere_levels) level.draw();
  } else {
    glDisable(GL_CULL_FACE);
    impostor.use();
    impostor.set("u_alpha", 1.0f);
    impostor.set("u_ambient_lift", 0.0f);
    sphere_quads.draw();
  }
}

// Arrows and points: first a faint ghost of the parts hidden behind bodies, then the visible parts.
void Renderer::Gpu::draw_marks() {
  auto draw_all = [&](float alpha) {
    glDisable(GL_CULL_FACE);
    flat.use();
    flat.set("u_alpha", alpha);
    arrow_mesh.draw();
    impostor.use();
    impostor.set("u_alpha", alpha);
    impostor.set("u_ambient_lift", 1.0f);
    point_quads.draw();
  };
  glEnable(GL_BLEND);
  // The edge image (if any) keeps the nearer of the ghost's outline and the body's behind it.
  glBlendEquationi(1, GL_MAX);
  // Colour over what is there; alpha adds up (over an opaque frame it stays 1).
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  draw_all(kArrowGhostAlpha);
  glBlendEquationi(1, GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  draw_all(1.0f);
}

void Renderer::Gpu::draw_ground(const DrawList& draw_list, const CameraView& camera) {
  const Vec3f centre(draw_list.camera.target.x(), draw_list.ground_height, draw_list.camera.target.z());
  for (const ShaderProgram* program : {&ground, &ground_shadow}) {
    program->set("u_background", to_vector(draw_list.background));
    program->set("u_ground_colour", kGroundColour);
    program->set("u_fog_start", 2.5f * camera.distance_to_target);
    program->set("u_fog_end", 0.25f * camera.far_distance);
  }
  ground.use();
  ground.set("u_ground_centre", centre);
  ground.set("u_ground_half_size", 0.7f * camera.far_distance);
  glDisable(GL_CULL_FACE);  // visible from below too
  ground_mesh.draw();
}

void Renderer::Gpu::clear(const Colour& colour) const {
  if (settings.transparent) glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  else glClearColor(colour.r, colour.g, colour.b, 1.0f);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// Starts the frame from the kept sky and ground, drawing them first if anything they depend on
// changed (the camera moved, say).
void Renderer::Gpu::prepare_background(const DrawList& draw_list, const CameraView& camera,
                                       const Vec3f& towards_light) {
  const BackgroundKey key{draw_list.camera, draw_list.background, draw_list.ground, draw_list.ground_height,
                          towards_light, subpixel_offset};
  if (!background_key || !(*background_key == key)) {
    background->bind_for_drawing();
    clear(draw_list.background);
    if (draw_list.ground && !settings.transparent) draw_ground(draw_list, camera);
    background_key = key;
  }
  background->copy_samples_to(target);
}

// After the ground: the shadow geometry, nudged towards the eye so it wins against the ground's
// depth, and hidden wherever a body is in front. Seen from below the ground, nothing is drawn.
void Renderer::Gpu::draw_ground_shadows(const DrawList& draw_list) {
  ground_shadow.use();
  ground_shadow.set("u_ground_height", draw_list.ground_height);
  // Slid onto the ground, the faces that face the light keep their winding seen from above and
  // the others turn over: culling draws each shadow pixel once (the lit faces tile the shadow).
  glEnable(GL_CULL_FACE);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -4.0f);
  ground_shadow.set("u_caster", int(ShadowCaster::disc));
  shadow_discs.draw();
  ground_shadow.set("u_caster", int(ShadowCaster::box));
  cube_mesh.draw();
  ground_shadow.set("u_caster", int(ShadowCaster::cylinder));
  cylinder_mesh.draw();
  ground_shadow.set("u_caster", int(ShadowCaster::face));
  draw_meshes();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
}

Renderer::Renderer(int width, int height, RendererSettings settings)
    : gpu_(std::make_unique<Gpu>(width, height, settings)) {}

Renderer::~Renderer() = default;

void Renderer::set_subpixel_offset(float x, float y) { gpu_->subpixel_offset = {x, y}; }

int Renderer::width() const { return gpu_->target.width(); }
int Renderer::height() const { return gpu_->target.height(); }
const RendererSettings& Renderer::settings() const { return gpu_->settings; }

const Frame& Renderer::draw(const DrawList& draw_list) {
  draw_into(draw_list, frame_);
  return frame_;
}

void Renderer::draw_into(const DrawList& draw_list, Frame& frame) {
  draw_into(draw_list, read_back_);
  finish(read_back_, frame);
}

void Renderer::draw_into(const DrawList& draw_list, ReadBack& read_back) {
  Gpu& gpu = *gpu_;
  gpu.context.make_current();

  CameraView camera = make_camera_view(draw_list.camera, width(), height());
  if (!gpu.subpixel_offset.isZero()) {
    // Clip x and y move by an offset times w: the image moves by it after the divide.
    Eigen::Matrix4f shift = Eigen::Matrix4f::Identity();
    shift(0, 3) = 2.0f * gpu.subpixel_offset.x() / float(width());
    shift(1, 3) = -2.0f * gpu.subpixel_offset.y() / float(height());
    camera.view_projection = shift * camera.view_projection;
  }
  const float light_length = draw_list.towards_light.norm();
  const Vec3f towards_light = std::isfinite(light_length) && light_length > 1e-6f
                                  ? Vec3f(draw_list.towards_light / light_length)
                                  : Vec3f(DrawList{}.towards_light.normalized());
  gpu.collect(draw_list, camera, towards_light);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);

  ShadowFrustum shadow;
  if (gpu.shadow_map) shadow = fit_shadow_frustum(draw_list, towards_light, gpu.shadow_map->size());
  if (shadow.has_casters) gpu.draw_shadows(shadow, towards_light);

  gpu.flat.set("u_view_projection", camera.view_projection);
  for (const ShaderProgram* program : {&gpu.lit, &gpu.impostor, &gpu.ground, &gpu.ground_shadow}) {
    program->set("u_view_projection", camera.view_projection);
    program->set("u_light_direction", towards_light);
    program->set("u_camera_position", draw_list.camera.position);
    program->set("u_light_view_projection", shadow.view_projection);
    program->set("u_shadows_enabled", shadow.has_casters ? 1 : 0);
    program->set("u_shadow_texel_world", shadow.texel_world);
  }
  if (gpu.background) {
    gpu.prepare_background(draw_list, camera, towards_light);
    gpu.target.bind_for_drawing();
    gpu.draw_bodies();
  } else {
    // The shadow map falls on the ground: draw it every frame, after the bodies so that the depth
    // test skips the pixels they hide.
    gpu.target.bind_for_drawing();
    gpu.clear(draw_list.background);
    gpu.target.clear_edges();
    gpu.draw_bodies();
    if (draw_list.ground && !gpu.settings.transparent) gpu.draw_ground(draw_list, camera);
  }
  if (draw_list.ground && !gpu.settings.transparent && gpu.settings.shadows == ShadowMethod::ground)
    gpu.draw_ground_shadows(draw_list);
  gpu.draw_marks();

  gpu.target.read_into(read_back);
  throw_on_gl_error("draw");
}

}  // namespace impulse::render
