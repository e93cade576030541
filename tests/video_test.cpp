// The whole path, decoded back: scene -> physics -> OSMesa frames -> PNG (libpng) and MP4
// (libavcodec), then read again and checked pixel by pixel.
#include "demos/render_scene.h"
#include "demos/scene_file.h"
#include "render/png_io.h"
#include "render/renderer.h"
#include "render/transforms.h"
#include "tests/video_decode.h"

#include <gtest/gtest.h>

#include <cmath>
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

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "impulse_video_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

demos::Scene small_scene(const fs::path& dir) {
  const fs::path path = dir / "ball.toml";
  std::ofstream(path) << kSceneText;
  return demos::load_scene(path.string());
}

struct Rgb { int r, g, b; };
Rgb pixel(const render::Frame& frame, int x, int y) {
  const uint8_t* p = &frame.rgba[(size_t(y) * frame.width + x) * 4];
  return {p[0], p[1], p[2]};
}
int distance(Rgb a, Rgb b) { return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b); }

// Where a world point lands in the image, by the same camera matrices the renderer uses.
Eigen::Vector2i project(const render::Camera& camera, int width, int height, const Eigen::Vector3f& point) {
  const Eigen::Matrix4f view = render::look_at(camera.position, camera.target, Eigen::Vector3f::UnitY());
  const Eigen::Matrix4f projection = render::perspective(camera.fov_y_degrees * float(M_PI) / 180, float(width) / height, 0.1f, 100);
  const Eigen::Vector4f clip = projection * view * point.homogeneous();
  const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
  return {int((ndc.x() + 1) / 2 * width), int((1 - ndc.y()) / 2 * height)};
}

TEST(Video, DecodedBackHasTheFramesAndTheBall) {
  const fs::path dir = scratch("decode");
  const demos::Scene scene = small_scene(dir);
  demos::RenderOptions options;
  options.video_path = (dir / "ball.mp4").string();
  demos::render_scene(scene, options);

  ASSERT_TRUE(fs::exists(options.video_path));
  EXPECT_FALSE(fs::exists(options.video_path + ".part"));
  const testing::DecodedVideo video = testing::decode_video(options.video_path);
  EXPECT_EQ(video.width, 320);
  EXPECT_EQ(video.height, 240);
  EXPECT_NEAR(video.fps, 30.0, 1e-6);
  ASSERT_EQ(video.frames.size(), 30u);

  const Eigen::Vector2i centre = project(scene.camera, 320, 240, {0, 0.5f, 0});
  EXPECT_NEAR(centre.x(), 160, 1);
  const Rgb background{int(0.92f * 255), int(0.94f * 255), int(0.97f * 255)};
  for (const render::Frame& frame : {video.frames.front(), video.frames.back()}) {
    const Rgb ball = pixel(frame, centre.x(), centre.y());
    const Rgb sky = pixel(frame, 5, 5);  // top-left corner: above the horizon
    EXPECT_LT(distance(sky, background), 24) << "sky " << sky.r << "," << sky.g << "," << sky.b;
    EXPECT_GT(distance(ball, sky), 120) << "ball " << ball.r << "," << ball.g << "," << ball.b;
    EXPECT_GT(ball.r, ball.b + 60) << "the ball is orange";
  }
}

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
  EXPECT_FALSE(fs::exists(options.video_path + ".part"));
}

}  // namespace
}  // namespace impulse
