// Heaps of boxes: 1000 bouncing (the benchmark's scene, restitution 0.5) never throw a body, and
// come to a complete rest with sleeping off (exercise 4); so does a box recorded rocking in one.
#include "physics/world.h"
#include "tests/bench_world.h"
#include "tests/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

// Before the bounce's time shift was bounded by a sub-step, a pair that barely parted after its
// hit (parting at 6 um/s) was shifted by -162 s of its velocity, and a box left at 159 m/s.
// Energy can only leave a heap with e < 1: it may never rise above its start (1 % for the soft
// contacts' rounding), and nothing may move faster than falling from the top layer (19.6 m/s).
TEST(Heap, ThousandBouncingBoxesNeverThrowABody) {
  WorldSettings settings;
  settings.sleep.enabled = true;
  World world = test::bench_world("boxes", settings, {0.5, 0.5});
  const Real start = world.record().kinetic_energy + world.record().potential_energy;
  Real most_energy = start, fastest = 0;
  for (int step = 0; step < 25 * 60; ++step) {
    world.step();
    most_energy = std::max(most_energy, world.record().kinetic_energy + world.record().potential_energy);
    for (const Body& body : world.bodies()) fastest = std::max(fastest, body.velocity.norm());
  }
  EXPECT_LT(most_energy - start, 0.01 * std::abs(start)) << "J";
  EXPECT_LT(fastest, 20.0) << "m/s";
}

// Exercise 4 ("do items come to a complete rest?") on the benchmark's heap of boxes, sleeping off,
// mu 0.4 and e 0.5 (one of the six materials heap_rest measures; tests/bench/README.md has all
// six, at rest by 20 s). From 20 s to 60 s no box's fastest point reaches 1 mm/s.
TEST(Heap, BoxesComeToRestWithSleepingOff) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world = test::bench_world("boxes", settings, {0.5, 0.4});
  EXPECT_LT(test::fastest_from(world, 20 * 60, 60 * 60), 0.001) << "m/s";
}

// The box recorded rocking on a box in the heap (test::add_rocking_boxes) settles: both moving
// boxes below 0.1 mm/s from 3 s to 5 s.
TEST(Heap, ABoxRockingOnABoxOfTheHeapSettles) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  World world(settings);
  ASSERT_EQ(test::add_rocking_boxes(world).size(), 2u);  // the other two are still
  EXPECT_LT(test::fastest_from(world, 3 * 60, 5 * 60), 1e-4) << "m/s";
}

}  // namespace
}  // namespace impulse::physics
