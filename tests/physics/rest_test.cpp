// Exercise 4: a spinning ball comes to rest where it spins (rolling and spinning friction).
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace impulse::physics {
namespace {

using namespace test;

// A ball spun about the vertical on the ground touches it at one point, about which friction has
// no lever: only the disc the soft contact presses (a few mm across) resists the spin. Without
// it the ball spun for ever (the heap of spheres kept spheres spinning at 0.2 m/s for a minute).
TEST(Rest, ABallSpinningOnTheSpotStops) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  add_ground(world, 0.0, 0.5);
  const int ball = add_sphere(world, Vec3(0, 0.25, 0), 0.25, 1.0, Vec3::Zero(), {0.0, 0.5});
  world.body(ball).angular_velocity = Vec3(0, 3, 0);
  for (int i = 0; i < 10 * 60; ++i) world.step();
  EXPECT_LT(world.bodies()[ball].angular_velocity.norm() * 0.25, 1e-3) << "m/s at its rim";
  EXPECT_LT((world.bodies()[ball].position - Vec3(0, 0.25, 0)).norm(), 0.001) << "m";
}

}  // namespace
}  // namespace impulse::physics
