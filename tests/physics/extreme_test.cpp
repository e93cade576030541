// Extreme but valid scenes: a 100:1 mass ratio stack; a fast sphere against a thin wall; a box
// resting for 10 000 steps.
#include "physics/world.h"
#include "tests/bench/bench_world.h"
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

using namespace test;

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
