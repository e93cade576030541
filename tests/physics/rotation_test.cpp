// Torque-free rotation: a box spun about its intermediate axis flips over and over (the
// tennis-racket, or Dzhanibekov, effect) while its kinetic energy and angular momentum stay;
// thin bodies spun fast stay bounded.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

using namespace test;

Real rotational_energy(const Body& b) { return b.angular_velocity.dot(b.inertia_world() * b.angular_velocity) / 2; }
Vec3 spin_momentum(const Body& b) { return b.inertia_world() * b.angular_velocity; }

struct Spin {
  Real energy_error = 0;    // largest |E - E0| / E0
  Real momentum_error = 0;  // largest ||L| - |L0|| / |L0|
  Real direction_error = 0; // largest |L - L0| / |L0|
  int flips = 0;            // times the intermediate axis went from along L to against it, or back
  Real fastest = 0;         // largest |w|
};

// Steps `seconds` and follows the rotation's invariants and the direction of the body's `axis`
// (local) against the angular momentum.
Spin spin(World& world, int body, const Vec3& axis, Real seconds) {
  const Body& b = world.bodies()[body];
  const Real e0 = rotational_energy(b);
  const Vec3 l0 = spin_momentum(b);
  Spin s;
  int side = (b.orientation * axis).dot(l0) > 0 ? 1 : -1;
  const int steps = int(std::lround(seconds / world.settings().time_step));
  for (int i = 0; i < steps; ++i) {
    world.step();
    const Vec3 l = spin_momentum(b);
    const Real e = rotational_energy(b);
    s.energy_error = std::max(s.energy_error, std::abs(e - e0) / e0);
    s.momentum_error = std::max(s.momentum_error, std::abs(l.norm() - l0.norm()) / l0.norm());
    s.direction_error = std::max(s.direction_error, (l - l0).norm() / l0.norm());
    s.fastest = std::max(s.fastest, b.angular_velocity.norm());
    const Real along = (b.orientation * axis).dot(l0.normalized());
    if (along * side < -0.9) {
      side = -side;
      ++s.flips;
    }
  }
  return s;
}

// Half extents 0.3 x 0.15 x 0.05 m: the moments about x, y, z are in the ratio 0.025 : 0.0925 :
// 0.1125, so y is the intermediate axis, and a small wobble grows at about 0.7 |w| per second.
const Vec3 kRacket(0.3, 0.15, 0.05);
const Vec3 kAboutMiddle(0.01, 6.0, 0.01);  // rad/s

// The world-frame angular momentum L is kept as a vector, so its direction as well as |L|.
void expect_kept(const Spin& s) {
  EXPECT_LT(s.energy_error, 0.001);
  EXPECT_LT(s.momentum_error, 0.001);
  EXPECT_LT(s.direction_error, 0.001);
}

TEST(Rotation, SpunAboutTheMiddleAxisFlipsAndKeepsEnergyAndMomentumWithoutGravity) {
  World world(without_gravity());
  const int box = add_box(world, Vec3::Zero(), kRacket, 0.5);
  world.body(box).angular_velocity = kAboutMiddle;
  const Spin s = spin(world, box, Vec3::UnitY(), 60);
  EXPECT_EQ(world.substeps(), world.settings().substeps);
  EXPECT_GE(s.flips, 10);  // 15 in a minute (the first at 2.7 s), the same at 1 to 48 sub-steps
  expect_kept(s);
}

// With gravity the free fall takes the fewest sub-steps (min_substeps): a coarser step.
TEST(Rotation, SpunAboutTheMiddleAxisWhileFallingFlipsAndKeepsEnergyAndMomentum) {
  World world;
  const int box = add_box(world, Vec3::Zero(), kRacket, 0.5);
  world.body(box).angular_velocity = kAboutMiddle;
  const Spin s = spin(world, box, Vec3::UnitY(), 60);
  EXPECT_EQ(world.substeps(), world.settings().min_substeps);
  EXPECT_GE(s.flips, 10);
  expect_kept(s);
}

// Thin bodies spun fast about an axis that is not a principal one: h |w| up to about 2 at the
// falling body's 240 Hz sub-steps, where an explicit gyroscopic term blows up. Nothing is gained
// or lost, and the spin stays as fast as it started.
TEST(Rotation, ThinPlateSpunFastAboutATiltedAxisStaysBounded) {
  World world;
  const int plate = add_box(world, Vec3::Zero(), Vec3(0.5, 0.002, 0.3), 1.0);
  world.body(plate).angular_velocity = Vec3(120, 40, -90);
  const Spin s = spin(world, plate, Vec3::UnitY(), 20);
  expect_kept(s);
  EXPECT_LT(s.fastest, 1.2 * Vec3(120, 40, -90).norm());
}

TEST(Rotation, LongThinRodSpunFastAboutATiltedAxisStaysBounded) {
  World world;
  const int rod = add_box(world, Vec3::Zero(), Vec3(1.0, 0.003, 0.004), 1.0);
  world.body(rod).angular_velocity = Vec3(300, 150, -200);
  const Spin s = spin(world, rod, Vec3::UnitX(), 20);
  expect_kept(s);
  EXPECT_LT(s.fastest, 1.2 * Vec3(300, 150, -200).norm());
}

// h |w| = 15 a sub-step: Newton's method alone does not converge, and the step is split.
TEST(Rotation, LongThinRodSpunFarTooFastStaysBounded) {
  World world;
  const int rod = add_box(world, Vec3::Zero(), Vec3(1.0, 0.003, 0.004), 1.0);
  world.body(rod).angular_velocity = Vec3(3000, 1500, -2000);
  const Spin s = spin(world, rod, Vec3::UnitX(), 5);
  expect_kept(s);
  EXPECT_LT(s.fastest, 1.2 * Vec3(3000, 1500, -2000).norm());
}

// Moments equal to a part in a million: the gyroscopic term is on, and tiny.
TEST(Rotation, NearlySymmetricBoxSpunFastStaysBounded) {
  World world;
  const int box = add_box(world, Vec3::Zero(), Vec3(0.2, 0.2, 0.2 * (1 + 1e-6)), 1.0);
  world.body(box).angular_velocity = Vec3(200, -50, 80);
  const Spin s = spin(world, box, Vec3::UnitZ(), 20);
  expect_kept(s);
}

}  // namespace
}  // namespace impulse::physics
