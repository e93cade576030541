// Listing 1 as printed (physics/workshop_listing.h): its penetration hack, and eq. 8's printed
// sign, the erratum, giving too little impulse.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

namespace impulse::physics {
namespace {

using namespace test;

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

}  // namespace
}  // namespace impulse::physics
