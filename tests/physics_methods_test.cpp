// The workshop's response methods side by side: what each conserves, and what each is for.
#include "tests/physics_test_scenes.h"

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

// Listing 1's bias adds 1.5 x penetration to every impulse: a ball that should not bounce
// (e = 0) gains speed from the depth it sank, which is the listing's flaw shown by the demos.
TEST(WorkshopMethod, PenetrationHackAddsImpulse) {
  World world(without_gravity(ResponseMethod::workshop));
  add_ground(world, 0, 0);
  const int ball = add_sphere(world, Vec3(0, 0.45, 0), 0.5, 1.0, Vec3(0, -1, 0), {0, 0});  // 5 cm deep
  world.step();
  const StepRecord& record = world.record();
  ASSERT_EQ(record.contacts.size(), 1u);
  EXPECT_NEAR(record.contacts[0].normal_impulse, 1.0 + 1.5 * 0.05, 1e-9);  // m v (1 + e) + 1.5 x depth
  EXPECT_NEAR(world.bodies()[ball].velocity.y(), 0.075, 1e-9);
}

// Eq. 8 as printed, -(1 - e) (the erratum the scene s3_restitution_erratum runs): at e = 1 a head-on
// hit gets no impulse but the hack fix's, where -(1 + e) gives 2 m v / (1 + m_a/m_b); at e = 0.7
// it gives 0.3 of the approach's impulse instead of 1.7.
TEST(WorkshopMethod, PrintedSignGivesTooLittleImpulse) {
  for (const bool printed : {false, true})
    for (const Real e : {0.7, 1.0}) {
      WorldSettings settings = without_gravity(ResponseMethod::workshop);
      settings.printed_eq8_sign = printed;
      World world(settings);
      add_sphere(world, Vec3(-0.5, 0, 0), 0.3, 1.0, Vec3(3, 0, 0), {e, 0});
      add_sphere(world, Vec3(0.09, 0, 0), 0.3, 2.0, Vec3::Zero(), {0, 0});  // 1 cm deep
      world.step();
      const StepRecord& record = world.record();
      ASSERT_EQ(record.contacts.size(), 1u);
      const Real expected = (printed ? 1 - e : 1 + e) * 3 / (1 / 1.0 + 1 / 2.0) + 1.5 * 0.01;  // eq. 8, hack fix
      EXPECT_NEAR(record.contacts[0].normal_impulse, expected, 1e-9) << "printed " << printed << ", e " << e;
    }
}

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
