// Boxes: restitution, rest without jiggle, energy and angular momentum.
#include "physics/pyramid.h"
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

using namespace test;

const Vec3 kUnit(0.5, 0.5, 0.5);

TEST(Box, LandingFlatReboundsToRestitutionSquaredOfDropHeight) {
  for (Real e : {0.3, 0.7, 1.0}) {
    World world;
    add_ground(world, 0, 0.5);
    const int box = add_box(world, Vec3(0, 0.5 + 1.0, 0), kUnit, 1.0, Quat::Identity(), Vec3::Zero(), {e, 0.5});
    bool bounced = false;
    Real peak = 0;
    for (int i = 0; i < 600; ++i) {
      world.step();
      const Body& b = world.bodies()[box];
      if (b.velocity.y() > 0) bounced = true;
      if (bounced && b.velocity.y() < 0) break;
      if (bounced) peak = std::max(peak, b.position.y() - 0.5);
    }
    EXPECT_NEAR(peak, e * e, 0.02 * e * e) << "e = " << e;
  }
}

TEST(Box, DroppedOnTheGroundComesToRestWithoutJiggle) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  add_ground_box(world);
  const Quat tilt(Eigen::AngleAxis<Real>(0.4, Vec3(1, 0, 1).normalized()));
  const int box = add_box(world, Vec3(0, 1.5, 0), kUnit, 1.0, tilt, Vec3::Zero(), {0.3, 0.6});
  for (int i = 0; i < 120; ++i) world.step();  // 2 s
  Real fastest = 0;
  const Vec3 resting = world.bodies()[box].position;
  for (int i = 0; i < 300; ++i) {
    world.step();
    const Body& b = world.bodies()[box];
    fastest = std::max(fastest, b.velocity.norm() + b.angular_velocity.norm() * 0.87);
  }
  EXPECT_LT(fastest, 1e-3) << "m/s: it jiggles";
  EXPECT_LT((world.bodies()[box].position - resting).norm(), 1e-4);
  EXPECT_NEAR(world.bodies()[box].position.y(), 0.5, 0.01);
}

TEST(Box, WithSleepingOnARestingBoxFallsAsleep) {
  World world;
  add_ground_box(world);
  const int box = add_box(world, Vec3(0, 1.5, 0), kUnit, 1.0);
  for (int i = 0; i < 180; ++i) world.step();
  EXPECT_FALSE(world.bodies()[box].awake);
}

// Off-centre hits on boxes conserve angular momentum about a fixed point (and momentum).
TEST(Box, OffCentreHitConservesAngularMomentum) {
  World world(without_gravity());
  add_box(world, Vec3(0, 0, 0), kUnit, 2.0, Quat(Eigen::AngleAxis<Real>(0.3, Vec3::UnitY())), Vec3::Zero(), {0.5, 0.4});
  add_sphere(world, Vec3(-2, 0.35, 0.2), 0.2, 1.0, Vec3(4, 0, 0), {0.5, 0.4});
  add_box(world, Vec3(0.3, 2.5, 0.1), kUnit, 1.0, Quat::Identity(), Vec3(0, -3, 0), {0.5, 0.4});
  const Vec3 before = angular_momentum_about_origin(world);
  const Vec3 momentum = linear_momentum(world);
  for (int i = 0; i < 90; ++i) world.step();
  EXPECT_LT((angular_momentum_about_origin(world) - before).norm(), 1e-5 * before.norm());
  EXPECT_LT((linear_momentum(world) - momentum).norm(), 1e-6 * momentum.norm());
  EXPECT_GT(world.bodies()[0].angular_velocity.norm(), 0.1) << "the hits did not spin the box";
}

// Total energy never rises in a closed system with e <= 1 and no driving joints.
TEST(Box, EnergyNeverRisesInABinOfBouncingBodies) {
  World world;
  add_ground(world, 0.8, 0.4);
  for (const Vec3& n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    BodyDef wall;
    wall.shape = Shape::plane(n, -3);
    wall.material = {0.8, 0.4};
    world.add_body(wall);
  }
  for (int i = 0; i < 24; ++i) {
    const Vec3 at(-2 + (i % 5), 1 + 1.2 * (i / 5), -1.5 + 0.7 * (i % 4));
    const Vec3 v(std::sin(i * 1.3) * 3, 0, std::cos(i * 0.7) * 3);
    if (i % 2) add_sphere(world, at, 0.3, 1.0, v, {0.8, 0.4});
    else add_box(world, at, Vec3(0.3, 0.25, 0.35), 1.0, Quat(Eigen::AngleAxis<Real>(i, Vec3(1, 2, 3).normalized())), v, {0.8, 0.4});
  }
  world.step();
  const StepRecord& first = world.record();
  const Real start = first.kinetic_energy + first.potential_energy;
  Real highest = start;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const StepRecord& r = world.record();
    highest = std::max(highest, r.kinetic_energy + r.potential_energy);
  }
  EXPECT_LE(highest - start, 0.01 * std::abs(start));
}

// A plank tumbling freely about a tilted axis keeps its angular momentum (the gyroscopic term)
// and does not gain energy.
TEST(Box, FreelyTumblingPlankKeepsItsAngularMomentum) {
  World world(test::without_gravity());
  const int plank = test::add_box(world, Vec3::Zero(), Vec3(1.0, 0.1, 0.3), 2.0);
  world.body(plank).angular_velocity = Vec3(0.3, 4.0, 1.0);  // near the unstable middle axis
  const Body& b = world.bodies()[plank];
  const Vec3 start = b.inertia_world() * b.angular_velocity;
  world.step();
  const Real energy = world.record().kinetic_energy;
  Real largest_error = 0, highest_energy = energy;
  for (int i = 0; i < 300; ++i) {
    world.step();
    highest_energy = std::max(highest_energy, world.record().kinetic_energy);
    largest_error = std::max(largest_error, (b.inertia_world() * b.angular_velocity - start).norm());
  }
  EXPECT_LT(largest_error, 0.01 * start.norm());
  EXPECT_LE(highest_energy, energy * 1.001);
}

}  // namespace
}  // namespace impulse::physics
