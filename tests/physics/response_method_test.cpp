// The workshop's response methods side by side (physics/response_method.h): what each conserves;
// the default impulse method; friction switched off.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

namespace impulse::physics {
namespace {

using namespace test;

class EveryImpulseMethod : public ::testing::TestWithParam<ResponseMethod> {};

// Impulses and penalty forces come in equal and opposite pairs: momentum is conserved in an
// oblique 3D hit between unequal spheres, friction on.
TEST_P(EveryImpulseMethod, ObliqueHitConservesLinearMomentum) {
  World world(without_gravity(GetParam()));
  add_sphere(world, Vec3(-1, 0.1, 0.05), 0.3, 1.0, Vec3(2, 0.2, -0.1), {0.6, 0.4});
  add_sphere(world, Vec3(1, -0.15, 0.2), 0.5, 2.5, Vec3(-1, 0, 0.3), {0.6, 0.4});
  const Vec3 before = linear_momentum(world);
  bool touched = false;
  for (int i = 0; i < 120; ++i) {
    world.step();
    touched = !world.record().contacts.empty() || touched;
  }
  ASSERT_TRUE(touched);
  EXPECT_LT((linear_momentum(world) - before).norm() / before.norm(), 1e-6) << method_name(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryImpulseMethod,
                         ::testing::Values(ResponseMethod::impulse, ResponseMethod::workshop, ResponseMethod::penalty),
                         [](const ::testing::TestParamInfo<ResponseMethod>& param) { return std::string(method_name(param.param)); });

// The default method: equal masses head on with e = 1 exchange their velocities.
TEST(ImpulseMethod, EqualMassesExchangeVelocities) {
  World world(without_gravity());
  const int a = add_sphere(world, Vec3(-1, 0, 0), 0.4, 2.0, Vec3(3, 0, 0), {1.0, 0.5});
  const int b = add_sphere(world, Vec3(1, 0, 0), 0.4, 2.0, Vec3(-0.5, 0, 0), {1.0, 0.5});
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_NEAR(world.bodies()[a].velocity.x(), -0.5, 1e-5);
  EXPECT_NEAR(world.bodies()[b].velocity.x(), 3.0, 1e-5);
  EXPECT_LT(world.bodies()[a].velocity.tail<2>().norm() + world.bodies()[b].velocity.tail<2>().norm(), 1e-9);
}

// Exercise 1: with tangential impulses off, a sphere sliding on the ground never starts to roll.
TEST(FrictionSwitch, OffLeavesASlidingSphereSliding) {
  WorldSettings settings;
  settings.contact.friction = false;
  World world(settings);
  add_ground(world, 0, 0.8);
  const int ball = add_sphere(world, Vec3(0, 0.5, 0), 0.5, 1.0, Vec3(3, 0, 0), {0, 0.8});
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_NEAR(world.bodies()[ball].velocity.x(), 3.0, 1e-9);
  EXPECT_NEAR(world.bodies()[ball].angular_velocity.norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace impulse::physics
