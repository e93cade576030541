// Coulomb friction: rolling, sticking, sliding, and the friction switch of exercise 1.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impulse::physics {
namespace {

using namespace test;

constexpr Real kG = 9.81;
const Real kSlope = std::numbers::pi / 6;  // 30 degrees, falling towards +x

int add_slope(World& world, Real friction) {
  BodyDef slope;
  slope.name = "slope";
  slope.shape = Shape::plane(Vec3(std::sin(kSlope), std::cos(kSlope), 0), 0);
  slope.material = {0, friction};
  return world.add_body(slope);
}

Vec3 down_slope() { return Vec3(std::cos(kSlope), -std::sin(kSlope), 0); }
Vec3 slope_normal() { return Vec3(std::sin(kSlope), std::cos(kSlope), 0); }
Quat on_slope() { return Quat(Eigen::AngleAxis<Real>(-kSlope, Vec3::UnitZ())); }

// Speed along the slope gained between t = 0.5 s and t = 1.5 s, over that second: the acceleration.
Real acceleration_down_slope(World& world, int body) {
  for (int i = 0; i < 30; ++i) world.step();
  const Real v0 = world.bodies()[body].velocity.dot(down_slope());
  for (int i = 0; i < 60; ++i) world.step();
  return world.bodies()[body].velocity.dot(down_slope()) - v0;
}

TEST(Friction, SphereRollsDownASlopeWithoutSlipping) {
  World world;
  add_slope(world, 0.6);
  const Real radius = 0.3;
  const int ball = add_sphere(world, slope_normal() * radius, radius, 2.0, Vec3::Zero(), {0, 0.6});
  EXPECT_NEAR(acceleration_down_slope(world, ball), 5.0 / 7.0 * kG * std::sin(kSlope), 0.02 * 5.0 / 7.0 * kG * std::sin(kSlope));
  const Body& b = world.bodies()[ball];
  EXPECT_NEAR(b.angular_velocity.norm() * radius, b.velocity.norm(), 0.01 * b.velocity.norm()) << "slipping";
}

TEST(Friction, BoxStaysOnASlopeWhenTanThetaIsBelowMu) {
  World world;
  add_slope(world, 0.7);  // tan 30 = 0.577 < 0.7
  const int box = add_box(world, slope_normal() * 0.5, Vec3(0.5, 0.5, 0.5), 1.0, on_slope(), Vec3::Zero(), {0, 0.7});
  for (int i = 0; i < 30; ++i) world.step();  // settle
  const Vec3 start = world.bodies()[box].position;
  for (int i = 0; i < 300; ++i) world.step();
  EXPECT_LT((world.bodies()[box].position - start).norm(), 1e-3);
}

// Three flat boxes stacked on the slope, well inside the friction cone (tan 30 = 0.58 of mu = 1)
// and from tipping (tan 30 < 0.5 m / 0.6 m), sleeping off: once settled nothing moves. The slope's
// normal has z = 0, where the friction directions built from it turn over with z's sign: a warm
// start carried over as two numbers, not as a vector, kicks the stack every few steps, and it
// flutters at 7 Hz and walks down the slope (1.3 mm/s, 4 mm in 15 s).
TEST(Friction, StackOnASlopeInsideTheFrictionConeStaysStill) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  add_slope(world, 1.0);
  std::vector<int> boxes;
  for (int i = 0; i < 3; ++i)
    boxes.push_back(add_box(world, slope_normal() * (0.2 + 0.4 * i), Vec3(0.5, 0.2, 0.5), 1.0, on_slope(), Vec3::Zero(), {0, 1.0}));
  for (int i = 0; i < 5 * 60; ++i) world.step();  // settle
  std::vector<Vec3> settled;
  for (int box : boxes) settled.push_back(world.bodies()[box].position);
  for (int i = 0; i < 15 * 60; ++i) world.step();
  for (int k = 0; k < 3; ++k) {
    const Body& box = world.bodies()[boxes[k]];
    EXPECT_LT((box.position - settled[k]).norm(), 1e-5) << "box " << k << " moved from 5 s to 20 s";
    EXPECT_LT(point_speed(box), 1e-5) << "box " << k << " still moving at 20 s";
  }
}

TEST(Friction, BoxSlidesDownASlopeWhenTanThetaIsAboveMu) {
  World world;
  add_slope(world, 0.3);
  const int box = add_box(world, slope_normal() * 0.5, Vec3(0.5, 0.5, 0.5), 1.0, on_slope(), Vec3::Zero(), {0, 0.3});
  const Real expected = kG * (std::sin(kSlope) - 0.3 * std::cos(kSlope));
  EXPECT_NEAR(acceleration_down_slope(world, box), expected, 0.03 * expected);
}

TEST(Friction, BoxSlidingAt20MetresPerSecondDeceleratesAtMuGInEveryDirection) {
  const Real mu = 0.5;
  for (int k = 0; k < 12; ++k) {
    const Real heading = 2 * std::numbers::pi * k / 12;
    const Vec3 direction(std::cos(heading), 0, std::sin(heading));
    World world;
    add_ground_box(world, {0, mu});
    const Quat yaw(Eigen::AngleAxis<Real>(0.3 * k, Vec3::UnitY()));
    const int box = add_box(world, Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0, yaw, 20 * direction, {0, mu});
    world.step();
    const Real v0 = world.bodies()[box].velocity.dot(direction);
    for (int i = 0; i < 60; ++i) world.step();
    const Real deceleration = v0 - world.bodies()[box].velocity.dot(direction);
    EXPECT_NEAR(deceleration, mu * kG, 0.02 * mu * kG) << "heading " << k * 30 << " degrees";
    EXPECT_LT(world.bodies()[box].velocity.cross(direction).norm(), 0.01) << "veered off";
  }
}

TEST(Friction, SpinningBallSetDownEndsUpRollingAtTwoSeventhsOfRadiusTimesSpin) {
  World world;
  add_ground(world, 0, 0.3);
  const Real radius = 0.4, spin = 20;
  const int ball = add_sphere(world, Vec3(0, radius, 0), radius, 1.0, Vec3::Zero(), {0, 0.3});
  world.body(ball).angular_velocity = Vec3(0, 0, spin);
  for (int i = 0; i < 180; ++i) world.step();
  const Body& b = world.bodies()[ball];
  EXPECT_NEAR(b.velocity.norm(), 2.0 / 7.0 * radius * spin, 0.03 * 2.0 / 7.0 * radius * spin);
  EXPECT_LT(b.velocity.x(), 0) << "the contact point moves +x, so friction drives the ball -x";
}

// Rolling resistance c: a torque up to c R N against rolling, so a ball rolling on the ground
// slows at c g / (1 + I / (m R^2)) = 5/7 c g (a solid ball), and without it rolls on.
TEST(Friction, RollingResistanceSlowsARollingBallAtFiveSeventhsOfCG) {
  for (const Real c : {0.0, 0.02}) {
    WorldSettings settings;
    settings.sleep.enabled = false;
    settings.contact.rolling_resistance = c;
    World world(settings);
    add_ground(world, 0, 0.5);
    const Real radius = 0.4, speed = 1;
    const int ball = add_sphere(world, Vec3(0, radius, 0), radius, 1.0, Vec3(speed, 0, 0), {0, 0.5});
    world.body(ball).angular_velocity = Vec3(0, 0, -speed / radius);
    for (int i = 0; i < 120; ++i) world.step();
    const Real expected = speed - 5.0 / 7.0 * c * 9.81 * 2.0;
    EXPECT_NEAR(world.bodies()[ball].velocity.x(), expected, 0.002) << "c = " << c;
  }
}

TEST(Friction, SwitchedOffABoxSlidingOnTheGroundKeepsItsSpeed) {
  WorldSettings settings;
  settings.contact.friction = false;
  World world(settings);
  add_ground_box(world, {0, 0.8});
  const int box = add_box(world, Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0, Quat::Identity(), Vec3(3, 0, 1), {0, 0.8});
  for (int i = 0; i < 180; ++i) world.step();
  EXPECT_NEAR((world.bodies()[box].velocity - Vec3(3, 0, 1)).norm(), 0, 1e-6);
}

}  // namespace
}  // namespace impulse::physics
