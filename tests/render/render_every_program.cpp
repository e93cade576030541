// A child process for RenderChildren (render_child_test.cpp): draws with every shader program the
// renderer has (lit bodies, cylinders and a flat mesh among them, sphere impostors and icospheres,
// flat arrows, points, ground, ground shadows, the shadow map's depth passes), paints the overlay
// and encodes an MP4, under whatever llvmpipe settings its environment holds. Exits 0 when every
// frame was drawn and encoded, 1 with the reason on an error; a crash is the parent's to see.
//
//   render_every_program OUTPUT_DIRECTORY
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "render/overlay_painter.h"
#include "render/renderer.h"
#include "render/video_encoder.h"
#include "tests/support/render_scenes.h"

namespace {

using namespace impulse;

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr int kFrames = 4;

struct Variant {
  const char* name;
  render::RendererSettings settings;
};

using render::Antialiasing;
const Variant kVariants[] = {
    {"impostors_ground_shadows", {.antialiasing = Antialiasing::msaa, .samples = 4,
                                  .shadows = render::ShadowMethod::ground, .spheres = render::SphereMethod::impostor}},
    {"icospheres_shadow_map", {.antialiasing = Antialiasing::msaa, .samples = 4,
                               .shadows = render::ShadowMethod::shadow_map, .shadow_map_size = 512,
                               .spheres = render::SphereMethod::tessellated}},
    {"impostors_shadow_map_no_msaa", {.antialiasing = Antialiasing::none, .shadows = render::ShadowMethod::shadow_map,
                                      .shadow_map_size = 512, .spheres = render::SphereMethod::impostor}},
    {"icospheres_no_shadows_no_msaa", {.antialiasing = Antialiasing::none, .shadows = render::ShadowMethod::none,
                                       .spheres = render::SphereMethod::tessellated}},
    {"impostors_ground_shadows_edges", {.antialiasing = Antialiasing::edges, .shadows = render::ShadowMethod::ground,
                                        .spheres = render::SphereMethod::impostor}},
    {"icospheres_shadow_map_edges", {.antialiasing = Antialiasing::edges, .shadows = render::ShadowMethod::shadow_map,
                                     .shadow_map_size = 512, .spheres = render::SphereMethod::tessellated}},
};

// A tetrahedron's four faces, counter-clockwise seen from outside.
std::shared_ptr<const std::vector<render::Vec3f>> tetrahedron() {
  const render::Vec3f a(0.4f, -0.2f, 0.0f), b(-0.2f, -0.2f, -0.35f), c(-0.2f, -0.2f, 0.35f), top(0.0f, 0.45f, 0.0f);
  return std::make_shared<const std::vector<render::Vec3f>>(std::vector<render::Vec3f>{a, c, b, a, b, top, b, c, top, c, a, top});
}

// Each frame moves the camera, so the kept background is redrawn too.
void draw_and_encode(const Variant& variant, const std::filesystem::path& directory) {
  render::Renderer renderer(kWidth, kHeight, variant.settings);
  render::OverlayPainter painter(kWidth, kHeight);
  render::VideoEncoder encoder((directory / (std::string(variant.name) + ".mp4")).string(),
                               {.width = kWidth, .height = kHeight, .fps = 30, .crf = 30});
  render::Frame frame;
  for (int i = 0; i < kFrames; ++i) {
    render::DrawList list = testing::bodies_scene();
    list.cylinders.push_back({{-2.3f, 0.6f, -0.6f}, 0.3f, 0.6f, render::Quatf::Identity(), {0.4f, 0.6f, 0.3f}});
    list.meshes.push_back({{2.3f, 0.7f, -0.6f}, render::Quatf::Identity(), tetrahedron(), {0.8f, 0.5f, 0.2f}});
    list.camera.position.x() += 0.2f * static_cast<float>(i);
    renderer.draw_into(list, frame);
    painter.paint(testing::lecture_overlay(), frame);
    encoder.add_frame(frame);
  }
  encoder.finish();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIRECTORY\n", argv[0]);
    return 2;
  }
  try {
    for (const Variant& variant : kVariants) draw_and_encode(variant, argv[1]);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "render_every_program: %s\n", error.what());
    return 1;
  }
  return 0;
}
