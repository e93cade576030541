// What the tests of a student's response share (tests/response, tests/grade): the listings of
// assets/workshop, scratch files, small worlds.
#pragma once
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
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

// The ground, a tilted box thrown onto it and a ball dropped onto it, every e = `restitution`.
inline physics::World tumbling_box_and_ball(const physics::WorldSettings& settings, physics::Real restitution = 0) {
  using physics::Vec3;
  physics::World world(settings);
  physics::BodyDef ground;
  ground.name = "ground";
  ground.shape = physics::Shape::plane(Vec3::UnitY(), 0);
  ground.material = {restitution, 0.5};
  world.add_body(ground);
  physics::BodyDef box;
  box.name = "box";
  box.shape = physics::Shape::box(Vec3(0.5, 0.5, 0.5));
  box.mass = 1;
  box.position = Vec3(0, 1, 0);
  box.orientation = physics::Quat(Eigen::AngleAxis<physics::Real>(0.3, Vec3(1, 2, 0.5).normalized()));
  box.velocity = Vec3(1, 0, 0);
  box.material = {restitution, 0.5};
  world.add_body(box);
  physics::BodyDef ball;
  ball.name = "ball";
  ball.shape = physics::Shape::sphere(0.3);
  ball.mass = 2;
  ball.position = Vec3(0.3, 2.2, 0.1);
  ball.material = {restitution, 0.5};
  world.add_body(ball);
  return world;
}

inline physics::Vec3 vec(const std::array<float, 3>& v) { return physics::Vec3(v[0], v[1], v[2]); }

// A body as the world hands it to a response, drawn at random: inverse mass and inertia (a box's,
// turned any way), velocities up to 4 m/s and 6 rad/s, e and mu the pair's. `still`: immovable.
inline physics::PlainBody random_body(std::mt19937& random, bool still) {
  std::uniform_real_distribution<float> unit(-1, 1), positive(0.2f, 2);
  physics::PlainBody body;
  for (float& x : body.centre) x = unit(random);
  body.inv_mass = still ? 0 : positive(random);
  const physics::Quat turn = physics::Quat(unit(random), unit(random), unit(random), unit(random) + 2).normalized();
  const physics::Vec3 inverse_moments(positive(random) * 6, positive(random) * 6, positive(random) * 6);
  const physics::Mat3 world = still ? physics::Mat3::Zero() : physics::Mat3(turn.toRotationMatrix() * inverse_moments.asDiagonal() * turn.toRotationMatrix().transpose());
  for (int i = 0; i < 9; ++i) body.world_inv_inertia[i] = float(world(i / 3, i % 3));
  for (int i = 0; i < 3; ++i) {
    body.lin_velocity[i] = still ? 0 : 4 * unit(random);
    body.ang_velocity[i] = still ? 0 : 6 * unit(random);
  }
  body.restitution = (unit(random) + 1) / 2;
  body.friction = (unit(random) + 1) / 2;
  return body;
}

// A contact between them: a point near both, any unit normal, a depth up to 4 cm; the pair's e and
// mu are a's (the world gives both bodies the pair's).
inline physics::PlainContact random_contact(std::mt19937& random, physics::PlainBody& a, physics::PlainBody& b) {
  std::uniform_real_distribution<float> unit(-1, 1);
  physics::PlainContact contact;
  const physics::Vec3 normal = physics::Vec3(unit(random), unit(random), unit(random)).normalized();
  for (int i = 0; i < 3; ++i) {
    contact.point[i] = (a.centre[i] + b.centre[i]) / 2 + 0.3f * unit(random);
    contact.normal[i] = float(normal[i]);
  }
  contact.penetration = 0.02f * (unit(random) + 1);
  contact.time_step = 1.0f / 60;
  b.restitution = a.restitution;
  b.friction = a.friction;
  return contact;
}

// The engine's view of a plain body, from its floats.
inline physics::RigidBody view(const physics::PlainBody& body) {
  physics::RigidBody rigid;
  rigid.centre = vec(body.centre);
  rigid.inv_mass = body.inv_mass;
  for (int i = 0; i < 9; ++i) rigid.world_inv_inertia(i / 3, i % 3) = body.world_inv_inertia[i];
  rigid.lin_velocity = vec(body.lin_velocity);
  rigid.ang_velocity = vec(body.ang_velocity);
  return rigid;
}

}  // namespace impulse::workshop::test
