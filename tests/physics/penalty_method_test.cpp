// The penalty method (physics/penalty_method.h): a spring that lets a resting ball sag.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

namespace impulse::physics {
namespace {

using namespace test;

// Section 1: penalty springs hold a resting ball with a small sag, k x = m g.
TEST(PenaltyMethod, RestingBallSagsByWeightOverStiffness) {
  WorldSettings settings;
  settings.method = ResponseMethod::penalty;
  World world(settings);
  add_ground(world);
  const int ball = add_sphere(world, Vec3(0, 0.5, 0), 0.5, 2.0);
  for (int i = 0; i < 300; ++i) world.step();
  const Real omega = 2 * 3.14159265358979 * settings.penalty.hertz;
  EXPECT_NEAR(0.5 - world.bodies()[ball].position.y(), 9.81 / (omega * omega), 1e-4);
  EXPECT_LT(world.bodies()[ball].velocity.norm(), 1e-3);
}

}  // namespace
}  // namespace impulse::physics
