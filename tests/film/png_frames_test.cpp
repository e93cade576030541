// PNG frames of whole scenes, read back (libpng) and against the MP4 decoded back (libavcodec); an
// unwritable output (the MP4 itself decoded back: render_video_test.cpp).
#include "demos/film/render_scene.h"
#include "demos/scene/scene_world.h"
#include "demos/scene/scene_file.h"
#include "render/png_io.h"
#include "render/renderer.h"
#include "tests/support/scene_scratch.h"
#include "tests/support/video_decode.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace impulse {
namespace {

namespace fs = std::filesystem;

// A small scene: one orange ball resting at the camera's target, so it is drawn at the centre
// (no marks: nothing is drawn over it).
constexpr const char* kSceneText = R"(
[scene]
duration = 1.0
[camera]
position = [0, 1.5, 6]
target = [0, 0.5, 0]
[video]
width = 320
height = 240
fps = 30
[draw]
contact_points = false
contact_normals = false
impulses = false
friction = false
sleeping = false
[[body]]
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
radius = 0.5
position = [0, 0.5, 0]
colour = "#e69f00"
)";

fs::path scratch(const std::string& name) { return testing::scratch("video_test", name); }

demos::Scene small_scene(const fs::path& dir) { return testing::scene_from(dir, kSceneText); }

TEST(Video, PngReadBackEqualsTheRenderedFrame) {
  const fs::path dir = scratch("png");
  const demos::Scene scene = small_scene(dir);
  physics::World world = demos::build_world(scene);
  render::Renderer renderer(scene.video.width, scene.video.height);
  world.step();
  const render::Frame& frame = renderer.draw(demos::make_draw_list(scene, world, world.record()));
  const std::string path = (dir / "frame.png").string();
  render::write_png(path, frame);
  const render::Frame back = render::read_png(path);
  EXPECT_EQ(back.width, frame.width);
  EXPECT_EQ(back.height, frame.height);
  EXPECT_TRUE(back.rgba == frame.rgba) << "the PNG differs from the frame it came from";
}

TEST(Video, PngFramesMatchTheVideoFrames) {
  const fs::path dir = scratch("both");
  const demos::Scene scene = small_scene(dir);
  demos::RenderOptions options;
  options.video_path = (dir / "ball.mp4").string();
  options.png_directory = (dir / "frames").string();
  demos::render_scene(scene, options);
  const testing::DecodedVideo video = testing::decode_video(options.video_path);
  ASSERT_EQ(video.frames.size(), 30u);
  for (int index : {0, 29}) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", index);
    const render::Frame png = render::read_png((dir / "frames" / name).string());
    ASSERT_EQ(png.rgba.size(), video.frames[index].rgba.size());
    double total = 0;
    for (size_t i = 0; i < png.rgba.size(); i += 4)
      for (int c = 0; c < 3; ++c) total += std::abs(int(png.rgba[i + c]) - int(video.frames[index].rgba[i + c]));
    EXPECT_LT(total / (png.rgba.size() / 4 * 3), 3.0) << "frame " << index << ": mean difference per channel";
  }
}

TEST(Video, UnwritableOutputThrowsAndLeavesNothing) {
  const fs::path dir = scratch("unwritable");
  const demos::Scene scene = small_scene(dir);
  demos::RenderOptions options;
  options.video_path = (dir / "no-such-dir" / "ball.mp4").string();
  EXPECT_THROW(demos::render_scene(scene, options), std::runtime_error);
  EXPECT_FALSE(fs::exists(options.video_path));
  EXPECT_FALSE(fs::exists(dir / "no-such-dir")) << "nor a temporary, nor its directory";
}

}  // namespace
}  // namespace impulse
