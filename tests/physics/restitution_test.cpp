// Issue 3's physical laws: restitution on the ground, and a head-on hit between two spheres.
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace impulse::physics {
namespace {

int add_ground(World& world, Real restitution) {
  BodyDef ground;
  ground.name = "ground";
  ground.shape = Shape::plane(Vec3::UnitY(), 0);
  ground.material.restitution = restitution;
  return world.add_body(ground);
}

class DropRebound : public ::testing::TestWithParam<Real> {};

// A ball dropped from rest rebounds to e^2 of its drop height (v' = e v, h = v^2 / 2g).
TEST_P(DropRebound, RisesToRestitutionSquaredOfDropHeight) {
  const Real e = GetParam();
  const Real radius = 0.25, drop_height = 1.0;  // height of the ball's bottom above the ground
  World world;
  add_ground(world, 0);  // the larger restitution of the pair wins
  BodyDef ball;
  ball.name = "ball";
  ball.shape = Shape::sphere(radius);
  ball.material.restitution = e;
  ball.position = Vec3(0, radius + drop_height, 0);
  const int id = world.add_body(ball);

  bool bounced = false;
  Real peak = 0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const Body& b = world.bodies()[id];
    if (!bounced && b.velocity.y() > 0) bounced = true;
    if (bounced) {
      if (b.velocity.y() < 0) break;  // past the top of the first rebound
      peak = std::max(peak, b.position.y() - radius);
    }
  }
  ASSERT_TRUE(bounced);
  EXPECT_NEAR(peak / drop_height, e * e, 0.02 * e * e) << "e = " << e << ", rebound " << peak << " m";
}

INSTANTIATE_TEST_SUITE_P(Restitution, DropRebound, ::testing::Values(0.3, 0.7, 1.0));

// Two spheres of different mass meet head on: momentum is conserved and they separate at e times
// the speed at which they approached (eq. 5).
TEST(HeadOn, ConservesMomentumAndSeparatesAtRestitutionTimesApproach) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  World world(settings);
  BodyDef light, heavy;
  light.name = "light";
  light.shape = Shape::sphere(0.5);
  light.mass = 1.0;
  light.material.restitution = 0.8;
  light.position = Vec3(-2, 1, 0);
  light.velocity = Vec3(3, 0, 0);  // total momentum 1.5 kg m/s
  heavy = light;
  heavy.name = "heavy";
  heavy.mass = 3.0;
  heavy.position = Vec3(2, 1, 0);
  heavy.velocity = Vec3(-0.5, 0, 0);
  const int a = world.add_body(light);
  const int b = world.add_body(heavy);

  const Vec3 momentum_before = 1.0 * light.velocity + 3.0 * heavy.velocity;
  const Real approach = (light.velocity - heavy.velocity).norm();
  bool hit = false;
  for (int i = 0; i < 120; ++i) {
    world.step();
    const StepRecord& record = world.record();
    hit = hit || !record.contacts.empty();
  }
  ASSERT_TRUE(hit);
  const Body& la = world.bodies()[a];
  const Body& hb = world.bodies()[b];
  const Vec3 momentum_after = la.mass * la.velocity + hb.mass * hb.velocity;
  EXPECT_LT((momentum_after - momentum_before).norm() / momentum_before.norm(), 1e-6);
  const Real separation_speed = hb.velocity.x() - la.velocity.x();
  EXPECT_NEAR(separation_speed, 0.8 * approach, 1e-4);
  EXPECT_LT(la.velocity.x(), 0);  // the light one bounces back
}

}  // namespace
}  // namespace impulse::physics
