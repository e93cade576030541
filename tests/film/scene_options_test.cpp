// What a scene asks the video for: the [camera] motion, [video] presets, [draw], [overlay],
// [[caption]] and [playback] tables, their errors, and the camera they produce.
#include "demos/film/camera_path.h"
#include "demos/film/playback_timeline.h"
#include "demos/film/plot_recorder.h"
#include "demos/scene/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBodies = R"(
[[body]]
shape = "plane"
[[body]]
name = "ball"
shape = "sphere"
position = [0, 2, 0]
)";

Scene load(const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "impulse_render_options_test";
  fs::create_directories(dir);
  const fs::path path = dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".toml");
  std::ofstream(path) << text << kBodies;
  return load_scene(path.string());
}

std::string error_of(const std::string& text) {
  try {
    load(text);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SceneOptions, ReadsEveryViewTable) {
  const Scene scene = load(R"(
[scene]
duration = 4
[camera]
follow = "ball"
[video]
quality = "low"
crf = 30
[draw]
velocities = true
impulse_scale = 0.5
contact_hold = 0.2
[overlay]
plots = ["kinetic_energy", "speed"]
plot_body = "ball"
label = "velocity"
[[caption]]
text = "First"
start = 1
end = 2
[[caption]]
text = "Then"
start = 2
[playback]
speed = 0.5
slow_motion_impulse = 3
)");
  EXPECT_EQ(scene.camera_motion.follow, "ball");
  EXPECT_EQ(scene.video.width, 854);  // the low preset ...
  EXPECT_EQ(scene.video.height, 480);
  EXPECT_EQ(scene.video.fps, 15);
  EXPECT_EQ(scene.video.crf, 30);     // ... with its CRF overridden
  EXPECT_TRUE(scene.draw.velocities);
  EXPECT_FLOAT_EQ(scene.draw.impulse_scale, 0.5f);
  EXPECT_FLOAT_EQ(scene.draw.contact_hold, 0.2f);
  ASSERT_EQ(scene.overlay.plots.size(), 2u);
  EXPECT_EQ(scene.overlay.plots[1], PlotKind::speed);
  EXPECT_EQ(scene.overlay.label, "velocity");
  ASSERT_EQ(scene.captions.size(), 2u);
  EXPECT_DOUBLE_EQ(scene.captions[1].end, 4.0);  // until the end of the scene
  EXPECT_DOUBLE_EQ(scene.playback.speed, 0.5);
  EXPECT_DOUBLE_EQ(scene.playback.slow_motion_impulse, 3.0);
}

TEST(SceneOptions, MediumIsTheDefaultQuality) {
  const Scene scene = load("");
  EXPECT_EQ(scene.video.width, 1280);
  EXPECT_EQ(scene.video.height, 720);
  EXPECT_EQ(scene.video.fps, 30);
}

TEST(SceneOptions, ErrorsNameTheLineFieldAndWhatToDo) {
  EXPECT_NE(error_of("[camera]\nfollow = \"bal\"\n").find(":2: [camera] field 'follow': no body is named 'bal' (bodies: 'body 1', 'ball')"),
            std::string::npos)
      << error_of("[camera]\nfollow = \"bal\"\n");
  EXPECT_NE(error_of("[[caption]]\nstart = 1\n").find("[[caption]] field 'text': missing"), std::string::npos);
  EXPECT_NE(error_of("[[caption]]\ntext = \"x\"\nstart = 2\nend = 1\n").find(":4: [[caption]] field 'end': must come after start"),
            std::string::npos);
  EXPECT_NE(error_of("[overlay]\nplots = [\"energy\"]\n").find("unknown plot 'energy' (known: kinetic_energy, momentum, speed)"),
            std::string::npos);
  EXPECT_NE(error_of("[overlay]\nplot_from = 60\n").find("field 'plot_from': must come before the scene's end"),
            std::string::npos);
  EXPECT_NE(error_of("[video]\nquality = \"ultra\"\n").find("unknown value 'ultra' (known: low, medium, high)"),
            std::string::npos);
  EXPECT_NE(error_of("[draw]\nimpulse = true\n").find("field 'impulse': unknown field"), std::string::npos);
  EXPECT_NE(error_of("[camera]\n[[camera.keyframe]]\ntime = 2\n[[camera.keyframe]]\ntime = 1\n")
                .find("keyframes must come in increasing time"),
            std::string::npos);
}

TEST(SceneOptions, CameraEasesBetweenKeyframes) {
  Scene scene = load(R"(
[camera]
position = [0, 2, 10]
target = [0, 1, 0]
[[camera.keyframe]]
time = 2
position = [10, 2, 0]
)");
  CameraPath path(scene);
  EXPECT_FLOAT_EQ(path.at(0, {}).position.x(), 0.0f);
  EXPECT_NEAR(path.at(1, {}).position.x(), 5.0f, 1e-4);   // halfway, eased
  EXPECT_LT(path.at(0.5, {}).position.x(), 2.5f);           // slow start
  EXPECT_FLOAT_EQ(path.at(2, {}).position.x(), 10.0f);
  EXPECT_FLOAT_EQ(path.at(3, {}).position.x(), 10.0f);      // stays at the last
  EXPECT_FLOAT_EQ(path.at(3, {}).target.y(), 1.0f);         // unset fields carry over
}

TEST(SceneOptions, CameraFollowsABodyKeepingItsOffset) {
  const Scene scene = load("[camera]\nposition = [0, 3, 10]\ntarget = [0, 2, 0]\nfollow = \"ball\"\n");
  CameraPath path(scene);
  ASSERT_EQ(path.followed_body(), 1);
  render::Camera camera = path.at(0, physics::Vec3(0, 2, 0));
  EXPECT_FLOAT_EQ(camera.target.y(), 2.0f);
  for (double t = 0.1; t <= 3.0; t += 0.1) camera = path.at(t, physics::Vec3(4, 2, 0));  // the ball moved 4 m
  EXPECT_NEAR(camera.target.x(), 4.0f, 0.01);
  EXPECT_NEAR(camera.position.x(), 4.0f, 0.01);
  EXPECT_NEAR(camera.position.z(), 10.0f, 1e-4);
}

}  // namespace
}  // namespace impulse::demos
