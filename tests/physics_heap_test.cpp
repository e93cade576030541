// A heap of 1000 bouncing boxes (the benchmark's scene, restitution 0.5): no body is ever thrown.
#include "physics/world.h"
#include "tests/bench_world.h"

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

}  // namespace
}  // namespace impulse::physics
