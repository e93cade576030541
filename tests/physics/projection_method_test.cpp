// The projection method (physics/projection_method.h): positions separated, velocities not.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

namespace impulse::physics {
namespace {

using namespace test;

// Section 1: projection moves the bodies apart but leaves their velocities alone, so a ball on
// the ground keeps gaining downward speed it never uses.
TEST(ProjectionMethod, SeparatesPositionsButNotVelocities) {
  WorldSettings settings;
  settings.method = ResponseMethod::projection;
  World world(settings);
  add_ground(world);
  const int ball = add_sphere(world, Vec3(0, 0.5, 0), 0.5, 1.0);
  for (int i = 0; i < 60; ++i) world.step();
  const Body& b = world.bodies()[ball];
  EXPECT_NEAR(b.position.y(), 0.5, 1e-9);        // never below the ground
  EXPECT_NEAR(b.velocity.y(), -9.81 * 1.0, 1e-6);  // a second of gravity, untouched
}

}  // namespace
}  // namespace impulse::physics
