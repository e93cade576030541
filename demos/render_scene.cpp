#include "demos/render_scene.h"

#include "render/png_io.h"
#include "render/renderer.h"
#include "render/video_encoder.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace impulse::demos {

namespace {

render::Vec3f to_float(const physics::Vec3& v) { return v.cast<float>(); }

// Contact normals: a teaching convention kept across all demos (README, "Colours").
constexpr render::Colour kNormalColour{0.84f, 0.37f, 0.00f};  // vermillion

std::string frame_file(const std::string& directory, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return (std::filesystem::path(directory) / name).string();
}

}  // namespace

physics::World build_world(const Scene& scene) {
  physics::World world(scene.world);
  for (const physics::BodyDef& def : scene.bodies) world.add_body(def);
  for (const physics::JointDef& def : scene.joints) world.add_joint(def);  // by index into bodies
  return world;
}

render::DrawList make_draw_list(const Scene& scene, const physics::World& world, const physics::StepRecord& record) {
  render::DrawList list;
  list.camera = scene.camera;
  list.ground = false;
  const auto& bodies = world.bodies();
  for (size_t i = 0; i < bodies.size(); ++i) {
    const physics::Body& body = bodies[i];
    switch (body.shape.type) {
      case physics::ShapeType::sphere:
        list.spheres.push_back({to_float(body.position), float(body.shape.radius), body.orientation.cast<float>(), scene.colours[i]});
        break;
      case physics::ShapeType::box:
        list.boxes.push_back({to_float(body.position), body.shape.half_extents.cast<float>(), body.orientation.cast<float>(), scene.colours[i]});
        break;
      case physics::ShapeType::plane:
        // The renderer draws one ground; a horizontal plane becomes it.
        if (body.shape.normal.y() > 0.999) {
          list.ground = true;
          list.ground_height = float(body.shape.offset);
        }
        break;
    }
  }
  if (scene.draw.contact_normals)
    for (const physics::ContactRecord& contact : record.contacts)
      list.arrows.push_back({to_float(contact.point), to_float(contact.normal) * scene.draw.normal_length, kNormalColour});
  return list;
}

void render_scene(const Scene& scene, const RenderOptions& options) {
  physics::World world = build_world(scene);
  const render::VideoSettings& video = scene.video;
  render::Renderer renderer(video.width, video.height);
  std::unique_ptr<render::VideoEncoder> encoder;
  if (!options.video_path.empty()) encoder = std::make_unique<render::VideoEncoder>(options.video_path, video);
  if (!options.png_directory.empty()) std::filesystem::create_directories(options.png_directory);

  const int frame_count = int(std::lround(scene.duration * video.fps));
  const auto start = std::chrono::steady_clock::now();
  physics::StepRecord shown = world.last_record();
  for (int frame = 0; frame < frame_count; ++frame) {
    // Step the world up to this frame's time; show the contacts of the last step taken.
    const double frame_time = double(frame) / video.fps;
    while (world.time() + scene.world.time_step / 2 <= frame_time) shown = world.step();
    const render::Frame& image = renderer.draw(make_draw_list(scene, world, shown));
    if (encoder) encoder->add_frame(image);
    if (!options.png_directory.empty()) render::write_png(frame_file(options.png_directory, frame), image);
    if (options.progress && (frame % 15 == 14 || frame + 1 == frame_count)) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "\r%s: frame %d/%d, %.1f frames/s ", scene.path.c_str(), frame + 1, frame_count, (frame + 1) / seconds);
      if (frame + 1 == frame_count) std::fputc('\n', stderr);
    }
  }
  if (encoder) encoder->finish();
}

}  // namespace impulse::demos
