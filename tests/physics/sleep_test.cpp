// Exercise 4: do bodies come to a complete rest? Sleeping and waking (physics/island.h).
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace impulse::physics {
namespace {

using namespace test;

TEST(Sleep, ABallThatStopsFallsAsleepAndWakesWhenHit) {
  World world;
  add_ground(world, 0.0, 0.6);
  const int ball = add_sphere(world, Vec3(0, 1.5, 0), 0.5, 1.0, Vec3::Zero(), {0.3, 0.6});
  int slept_at = -1;
  for (int i = 0; i < 300 && slept_at < 0; ++i) {
    world.step();
    if (!world.bodies()[ball].awake) slept_at = i;
  }
  ASSERT_GE(slept_at, 0) << "never fell asleep";
  EXPECT_NEAR(world.bodies()[ball].position.y(), 0.5, 0.01);

  // Asleep, it is not simulated: it stays put.
  const Vec3 resting = world.bodies()[ball].position;
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_EQ(world.bodies()[ball].position, resting);

  // A second ball dropped on it wakes it.
  const int hammer = add_sphere(world, Vec3(0.2, 2.5, 0), 0.3, 1.0);
  bool woke = false;
  for (int i = 0; i < 90 && !woke; ++i) {
    world.step();
    woke = world.bodies()[ball].awake;
  }
  EXPECT_TRUE(woke);
  EXPECT_GT(world.bodies()[hammer].position.y(), 0.5) << "the hammer passed through";
}

// A ball rolling along a sleeping box, 1 cm from its side, neither touches nor closes on it: the
// box sleeps on. When any nearby contact woke a sleeper, it woke at once, slept again 0.5 s later, and
// so on; in a resting heap the islands kept waking each other and the heap never slept.
TEST(Sleep, ABallRollingAlongASleepingBoxLeavesItAsleep) {
  World world;
  add_ground(world, 0.0, 0.5);
  const int box = add_box(world, Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 3.5), 1.0);  // a long box
  const int ball = add_sphere(world, Vec3(1.01, 0.5, -2.5), 0.5, 1.0, Vec3(0, 0, 0.5));
  world.body(ball).angular_velocity = Vec3(1.0, 0, 0);  // rolling: v = w x (-R up)
  int woken = 0;
  bool was_awake = true;
  for (int i = 0; i < 12 * 60; ++i) {
    world.step();
    const bool awake = world.bodies()[box].awake;
    if (awake && !was_awake) ++woken;
    was_awake = awake;
    if (i == 60) {
      ASSERT_FALSE(awake) << "the box should be asleep after 1 s";
    }
  }
  EXPECT_EQ(woken, 0) << "times the passing ball woke the box";
  EXPECT_GT(world.bodies()[ball].position.z(), 2.5) << "the ball rolled on along it";
}

// ...but a ball thrown at it wakes it before it arrives: the box is pushed, not hit as if static.
TEST(Sleep, ABallThrownAtASleepingBoxWakesItAndPushesIt) {
  World world;
  add_ground(world, 0.0, 0.5);
  const int box = add_box(world, Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0);
  for (int i = 0; i < 60; ++i) world.step();
  ASSERT_FALSE(world.bodies()[box].awake);
  add_sphere(world, Vec3(-2, 0.5, 0), 0.25, 2.0, Vec3(4, 0, 0));
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_GT(world.bodies()[box].position.x(), 0.1) << "m: the box was not pushed";
}

// Newton's first law with sleeping on: a body that nothing holds moves on however slowly it moves.
// A ball drifting at 3 cm/s in zero gravity, and one sliding at 3 cm/s on a frictionless floor,
// cover their 12 cm in 4 s.
TEST(Sleep, ABodyNothingHoldsNeverSleeps) {
  WorldSettings drifting;
  drifting.gravity = Vec3::Zero();
  World space(drifting);
  const int drifter = add_sphere(space, Vec3::Zero(), 0.5, 1.0, Vec3(0.03, 0, 0));
  World floor;
  add_ground(floor, 0.0, 0.0);
  const int slider = add_sphere(floor, Vec3(0, 0.5, 0), 0.5, 1.0, Vec3(0.03, 0, 0));
  for (int i = 0; i < 4 * 60; ++i) {
    space.step();
    floor.step();
  }
  EXPECT_TRUE(space.bodies()[drifter].awake);
  EXPECT_NEAR(space.bodies()[drifter].position.x(), 0.12, 1e-9);
  EXPECT_TRUE(floor.bodies()[slider].awake);
  EXPECT_NEAR(floor.bodies()[slider].position.x(), 0.12, 1e-4);
}

// What holds a body lets it sleep: a ball hanging still on a rod from a fixed point, with no floor.
TEST(Sleep, ABallHangingStillFromTheWorldFallsAsleep) {
  World world;
  const int ball = add_sphere(world, Vec3(0, 1, 0), 0.2, 1.0);
  JointDef rod;
  rod.type = JointType::distance;
  rod.body_a = kWorld;
  rod.body_b = ball;
  rod.anchor_a = Vec3(0, 2, 0);
  rod.anchor_b = Vec3(0, 1, 0);
  world.add_joint(rod);
  for (int i = 0; i < 2 * 60; ++i) world.step();
  EXPECT_FALSE(world.bodies()[ball].awake);
}

TEST(Sleep, OffKeepsEverythingAwake) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  add_ground(world);
  const int ball = add_sphere(world, Vec3(0, 0.5, 0), 0.5, 1.0);
  for (int i = 0; i < 180; ++i) world.step();
  EXPECT_TRUE(world.bodies()[ball].awake);
  EXPECT_LT(world.bodies()[ball].velocity.norm(), 1e-3);
}

}  // namespace
}  // namespace impulse::physics
