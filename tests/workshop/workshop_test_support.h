// What the workshop's tests share: the listings of assets/workshop, scratch files, small worlds.
#pragma once
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace impulse::workshop::test {

inline std::string listing(const std::string& name) { return std::string(IMPULSE_SOURCE_DIR) + "/assets/workshop/" + name; }

inline std::string read(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// A file of this test program's own, under the build's scratch directory.
inline std::string scratch_file(const std::string& name, const std::string& text) {
  const std::filesystem::path directory = std::filesystem::path(IMPULSE_TEST_SCRATCH) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(directory);
  const std::string path = (directory / name).string();
  std::ofstream(path) << text;
  return path;
}

// The ground, a tilted box thrown onto it and a ball dropped onto it, every e = 0.
inline physics::World tumbling_box_and_ball(const physics::WorldSettings& settings) {
  using physics::Vec3;
  physics::World world(settings);
  physics::BodyDef ground;
  ground.name = "ground";
  ground.shape = physics::Shape::plane(Vec3::UnitY(), 0);
  ground.material = {0, 0.5};
  world.add_body(ground);
  physics::BodyDef box;
  box.name = "box";
  box.shape = physics::Shape::box(Vec3(0.5, 0.5, 0.5));
  box.mass = 1;
  box.position = Vec3(0, 1, 0);
  box.orientation = physics::Quat(Eigen::AngleAxis<physics::Real>(0.3, Vec3(1, 2, 0.5).normalized()));
  box.velocity = Vec3(1, 0, 0);
  box.material = {0, 0.5};
  world.add_body(box);
  physics::BodyDef ball;
  ball.name = "ball";
  ball.shape = physics::Shape::sphere(0.3);
  ball.mass = 2;
  ball.position = Vec3(0.3, 2.2, 0.1);
  ball.material = {0, 0.5};
  world.add_body(ball);
  return world;
}

}  // namespace impulse::workshop::test
