// Long runs and extreme but valid scenes: the heaps of ../shared/bench/SCENES.md for a
// minute with nothing non-finite, nothing through the ground and no energy from nowhere; a 100:1
// mass ratio stack; a fast sphere against a thin wall; a box resting for 10 000 steps.
#include "physics/world.h"
#include "tests/bench_world.h"
#include "tests/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

using namespace test;

// SCENES.md's heap of 1000 boxes or of 1000 spheres, sleeping off, materials as the benchmark's.
World heap(const std::string& name) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  return bench_world(name, settings, {0.0, 0.5});
}

class LongRun : public ::testing::TestWithParam<const char*> {};

// A non-finite state would stop step() with an error; besides, every centre stays above the ground
// (its top is y = 0) and the total energy never rises above its start (1 % for the soft contacts).
TEST_P(LongRun, SixtySecondsStayFiniteAboveTheGroundAndWithinTheirEnergy) {
  World world = heap(GetParam());
  const Real start = world.record().kinetic_energy + world.record().potential_energy;
  Real most_energy = start, lowest = INFINITY;
  for (int step = 0; step < 60 * 60; ++step) {
    ASSERT_NO_THROW(world.step()) << "step " << step;
    most_energy = std::max(most_energy, world.record().kinetic_energy + world.record().potential_energy);
    for (const Body& body : world.bodies())
      if (!body.is_static()) lowest = std::min(lowest, body.position.y());
  }
  EXPECT_GT(lowest, 0.1) << "m: a centre at or below the ground's top";
  EXPECT_LT(most_energy - start, 0.01 * std::abs(start)) << "J";
}

INSTANTIATE_TEST_SUITE_P(Heap, LongRun, ::testing::Values("boxes", "spheres"));

// Exercise 4 on the heap of spheres (mu 0.5, e 0; one of the 12 materials measured in
// physics/README.md): with rolling resistance 0.01, from 20 s to 60 s no sphere's fastest point
// reaches 1 mm/s (measured: 0.14 mm/s). Without it a few spheres roll on over the floor at 1 to
// 5 mm/s for ever, as a rigid ball on a rigid plane does.
TEST(Heap, SpheresComeToRestWithSleepingOff) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  settings.contact.rolling_resistance = 0.01;
  World world = bench_world("spheres", settings, {0.0, 0.5});
  EXPECT_LT(fastest_from(world, 20 * 60, 60 * 60), 0.001) << "m/s";
}

// A 100 kg box on a 1 kg box on the ground, sleeping off: the light one is not squeezed out or
// through, and the stack comes to rest (were the ground's contacts twice as stiff as the others,
// it would rattle at 0.1-0.3 m/s for ever and wander by centimetres).
TEST(Extreme, HundredToOneMassStackStandsStill) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  add_ground_box(world);
  const int light = add_box(world, Vec3(0, 0.5, 0), Vec3::Constant(0.5), 1.0);
  const int heavy = add_box(world, Vec3(0, 1.5, 0), Vec3::Constant(0.5), 100.0);
  const Real fastest = fastest_from(world, 5 * 60, 10 * 60);  // the two boxes: the ground is still
  const auto& bodies = world.bodies();
  EXPECT_NEAR(bodies[light].position.y(), 0.5, 0.01);
  EXPECT_NEAR(bodies[heavy].position.y(), 1.5, 0.02);
  EXPECT_LT(Vec3(bodies[heavy].position.x(), 0, bodies[heavy].position.z()).norm(), 0.001) << "m from the axis";
  EXPECT_LT(fastest, 0.001) << "m/s, from 5 s to 10 s";
}

// A 10 cm sphere at 100 m/s (1.7 m a step at 60 Hz) against a static wall 5 cm thick: the
// broad and narrow phases look ahead over the step (speculative contacts), so the sphere stops at
// the wall instead of passing through it.
TEST(Extreme, FastSphereDoesNotTunnelThroughAThinWall) {
  World world(without_gravity());
  add_sphere(world, Vec3(-3, 0, 0), 0.1, 1.0, Vec3(100, 0, 0), {0.0, 0.5});
  BodyDef wall;
  wall.shape = Shape::box(Vec3(0.025, 2, 2));
  wall.is_static = true;
  world.add_body(wall);
  for (int step = 0; step < 60; ++step) world.step();
  EXPECT_LT(world.bodies()[0].position.x(), -0.1) << "the sphere is past the wall";
}

// A box on the ground for 10 000 steps, sleeping off: it neither creeps nor jiggles.
TEST(Extreme, ABoxRestsTenThousandSteps) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  add_ground_box(world);
  const int box = add_box(world, Vec3(0, 0.5, 0), Vec3::Constant(0.5), 1.0);
  Real fastest_late = 0;
  for (int step = 0; step < 10000; ++step) {
    world.step();
    if (step >= 5000) fastest_late = std::max(fastest_late, world.bodies()[box].velocity.norm());
  }
  const Body& body = world.bodies()[box];
  EXPECT_LT((body.position - Vec3(0, 0.5, 0)).norm(), 0.005) << "m";
  EXPECT_LT(body.orientation.angularDistance(Quat::Identity()), 1e-3) << "rad";
  EXPECT_LT(fastest_late, 1e-3) << "m/s";
}

}  // namespace
}  // namespace impulse::physics
