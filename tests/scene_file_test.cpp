// Scene files: good ones load, bad ones are refused with file, line, field and reason.
#include "demos/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace impulse::demos {
namespace {

std::string write_scene(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("impulse_scene_test_" + name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& text) {
  const std::string path = write_scene(::testing::UnitTest::GetInstance()->current_test_info()->name(), text);
  try {
    load_scene(path);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SceneFile, LoadsTheBounceScene) {
  const Scene scene = load_scene(std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/bounce.toml");
  ASSERT_EQ(scene.bodies.size(), 4u);
  EXPECT_EQ(scene.bodies[0].shape.type, physics::ShapeType::plane);
  EXPECT_EQ(scene.bodies[1].name, "dropped ball");
  EXPECT_DOUBLE_EQ(scene.bodies[1].material.restitution, 0.7);
  EXPECT_DOUBLE_EQ(scene.world.time_step, 1.0 / 60);
  EXPECT_EQ(scene.video.width, 1280);
  EXPECT_EQ(scene.video.fps, 30);
}

TEST(SceneFile, SyntaxErrorNamesFileAndLine) {
  const std::string error = error_of("[world]\ngravity = [0, -9.81, 0]\nstep_rate = = 60\n");
  EXPECT_NE(error.find("SyntaxErrorNamesFileAndLine.toml:3:"), std::string::npos) << error;
}

TEST(SceneFile, ImpossibleValueNamesLineFieldAndReason) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\n\n[[body]]\nname = \"bad\"\nshape = \"sphere\"\nradius = 0\n");
  EXPECT_NE(error.find(":7: [[body]] 'bad' field 'radius': must be > 0 and <= 1000, got 0"), std::string::npos) << error;
}

TEST(SceneFile, NegativeMassIsRefused) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\nmass = -2\n");
  EXPECT_NE(error.find("field 'mass': must be > 0 and <= 1e+09, got -2"), std::string::npos) << error;
}

TEST(SceneFile, RestitutionAboveOneIsRefused) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\nrestitution = 1.5\n");
  EXPECT_NE(error.find("field 'restitution': must be >= 0 and <= 1, got 1.5"), std::string::npos) << error;
}

TEST(SceneFile, UnknownFieldIsNamed) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\nradiuss = 1\n");
  EXPECT_NE(error.find(":3: [[body]] 'body 1' field 'radiuss': unknown field"), std::string::npos) << error;
}

TEST(SceneFile, WrongTypeIsNamed) {
  const std::string error = error_of("[camera]\nposition = [0, 1]\n[[body]]\nshape = \"sphere\"\n");
  EXPECT_NE(error.find(":2: [camera] field 'position': must be an array of three numbers"), std::string::npos) << error;
}

TEST(SceneFile, MissingFileIsReported) {
  try {
    load_scene("/nonexistent/scene.toml");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.toml"), std::string::npos) << error.what();
  }
}

TEST(SceneFile, NoBodiesIsRefused) {
  EXPECT_NE(error_of("[world]\nsubsteps = 4\n").find("no bodies"), std::string::npos);
}

}  // namespace
}  // namespace impulse::demos
