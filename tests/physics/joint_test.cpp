// Exercise 5: impulse constraints that join bodies (pendulum, hinge, rope, Newton's cradle).
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impulse::physics {
namespace {

using namespace test;

JointDef rod_to_world(int body, const Vec3& pivot, const Vec3& attach, bool rope = false) {
  JointDef def;
  def.type = JointType::distance;
  def.body_a = kWorld;
  def.body_b = body;
  def.anchor_a = pivot;
  def.anchor_b = attach;
  def.rope = rope;
  return def;
}

// A small-angle pendulum on a rod swings with T = 2 pi sqrt(L / g).
TEST(Joints, RodPendulumSwingsWithTheTextbookPeriod) {
  World world;
  const Real length = 1.5, angle = 0.1;
  const Vec3 pivot(0, 3, 0);
  const Vec3 bob = pivot + length * Vec3(std::sin(angle), -std::cos(angle), 0);
  const int ball = add_sphere(world, bob, 0.05, 1.0);
  world.add_joint(rod_to_world(ball, pivot, bob));
  // Time between successive crossings of x = 0 in the same direction.
  std::vector<Real> crossings;
  Real previous_x = bob.x();
  for (int i = 0; i < 60 * 12 && crossings.size() < 4; ++i) {
    world.step();
    const Real x = world.bodies()[ball].position.x();
    if (previous_x > 0 && x <= 0) crossings.push_back(world.time() - world.settings().time_step * x / (x - previous_x));
    previous_x = x;
  }
  ASSERT_EQ(crossings.size(), 4u);
  const Real period = (crossings[3] - crossings[0]) / 3;
  EXPECT_NEAR(period, 2 * std::numbers::pi * std::sqrt(length / 9.81), 0.01 * period);
  EXPECT_NEAR((world.bodies()[ball].position - pivot).norm(), length, 2e-3) << "the rod stretched";
}

// A rope holds a ball hanging still at its length, and lets it fall freely while slack.
TEST(Joints, RopeOnlyPulls) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  const Vec3 pivot(0, 3, 0);
  const int ball = add_sphere(world, Vec3(0, 2.5, 0), 0.1, 1.0);
  JointDef rope = rod_to_world(ball, pivot, Vec3(0, 2.5, 0), true);
  rope.length = 1.0;  // starts 0.5 m slack
  world.add_joint(rope);
  world.step();
  EXPECT_NEAR(world.bodies()[ball].velocity.y(), -9.81 / 60, 1e-9) << "a slack rope must not pull";
  for (int i = 0; i < 240; ++i) world.step();
  EXPECT_NEAR(world.bodies()[ball].position.y(), 2.0, 3e-3);
  EXPECT_LT(world.bodies()[ball].velocity.norm(), 0.02);
}

// A hinge about z: a rod-like chain of two spheres pinned at the top swings in the x-y plane only.
TEST(Joints, HingeKeepsMotionInItsPlane) {
  World world;
  const int a = add_sphere(world, Vec3(0.5, 3, 0), 0.1, 1.0, Vec3(0, 0, 0));
  JointDef hinge;
  hinge.type = JointType::hinge;
  hinge.body_a = kWorld;
  hinge.body_b = a;
  hinge.anchor = Vec3(0, 3, 0);
  hinge.axis = Vec3::UnitZ();
  world.add_joint(hinge);
  world.body(a).velocity = Vec3(0, 0, 0.8);  // a push along the axis: the hinge must refuse it
  world.body(a).angular_velocity = Vec3(1, 0.5, 0);
  for (int i = 0; i < 120; ++i) world.step();
  const Body& body = world.bodies()[a];
  EXPECT_NEAR(body.position.z(), 0, 5e-3);
  EXPECT_NEAR((body.position - Vec3(0, 3, 0)).norm(), 0.5, 5e-3);
  EXPECT_LT(std::abs(body.angular_velocity.x()) + std::abs(body.angular_velocity.y()), 1e-3);
}

// Five touching balls on rods: the first one's momentum passes through to the last.
TEST(Joints, NewtonsCradlePassesMomentumThrough) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  const Real radius = 0.1, length = 1.0;
  std::vector<int> balls;
  for (int i = 0; i < 5; ++i) {
    const Vec3 pivot(2 * radius * i, 2, 0);
    Vec3 position = pivot - Vec3(0, length, 0);
    if (i == 0) position = pivot + length * Vec3(-std::sin(0.5), -std::cos(0.5), 0);  // raised 0.5 rad
    balls.push_back(add_sphere(world, position, radius, 1.0, Vec3::Zero(), {1.0, 0.0}));
    world.add_joint(rod_to_world(balls.back(), pivot, position));
  }
  Real incoming = 0;
  int hit_step = -1;
  for (int i = 0; i < 120 && hit_step < 0; ++i) {
    incoming = world.bodies()[balls[0]].velocity.norm();
    world.step();
    for (const ContactRecord& c : world.record().contacts)
      if (c.normal_impulse > 1e-6) hit_step = i;  // the arrival, not the touching balls' rounding
  }
  ASSERT_GE(hit_step, 0) << "the first ball never arrived";
  // Over the next 0.1 s: the far ball's top speed (it leaves at once, then climbs and slows),
  // and the others' speeds at the end.
  Real far_ball = world.bodies()[balls[4]].velocity.norm();
  for (int i = 0; i < 6; ++i) {
    world.step();
    far_ball = std::max(far_ball, world.bodies()[balls[4]].velocity.norm());
  }
  EXPECT_GE(far_ball, 0.95 * incoming);
  for (int i = 0; i < 4; ++i) EXPECT_LT(world.bodies()[balls[i]].velocity.norm(), 0.05 * incoming) << "ball " << i;
}

}  // namespace
}  // namespace impulse::physics
