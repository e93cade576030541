// A state that is no longer finite stops the step, naming the body (World::step).
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace impulse::physics {
namespace {

using namespace test;

// A NaN never reaches the renderer: the step stops with an error naming the body.
TEST(Finite, NonFiniteStateStopsTheStepNamingTheBody) {
  World world;
  test::add_ground(world);
  const int ball = test::add_sphere(world, Vec3(0, 2, 0), 0.5, 1.0);
  world.body(ball).name = "the red ball";
  world.body(ball).velocity = Vec3(0, std::numeric_limits<Real>::quiet_NaN(), 0);
  try {
    world.step();
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("'the red ball'"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace impulse::physics
