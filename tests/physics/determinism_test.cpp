// Determinism: the same world gives the same bits run after run, with one thread or two, and on
// every x86-64 machine (as Box2D's test/test_determinism.c does): a scene that exercises every part
// of the step is hashed after a few hundred steps and compared with a constant written here.
//
// The constant holds because the physics is computed the same way on any x86-64 CPU (physics/README.md,
// "The same bits on every machine"): baseline x86-64 code (SSE2, no -march=native, no runtime CPU
// dispatch), -ffp-contract=off, no fast-math, and no call into glibc's libm functions that choose
// their code by the CPU (sin, cos, exp, pow, ...). Neither do these tests: their orientations are
// quaternions of exact numbers, normalised (a square root is exact everywhere).
//
// When the physics changes on purpose, the constants change in the same commit, with the reason
// in its message (tests/README.md). A change that was not meant to alter the physics must leave
// them as they are.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace impulse::physics {
namespace {

using namespace test;

// FNV-1a over the bytes of every body's position and orientation, in the order they were added.
uint64_t state_hash(const World& world) {
  uint64_t hash = 1469598103934665603ull;
  auto mix = [&](const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  };
  for (const Body& b : world.bodies()) {
    mix(b.position.data(), sizeof(Real) * 3);
    mix(b.orientation.coeffs().data(), sizeof(Real) * 4);
  }
  return hash;
}

// A small turn that needs no sine: the quaternion (1, x, y, z) normalised.
Quat tilt(Real x, Real y, Real z) { return Quat(1, x, y, z).normalized(); }

std::string hex(uint64_t hash) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(hash));
  return text;
}

// Every part of the step at once: two stacks of boxes (one of them tilted a little so that it
// topples), a heap of boxes and spheres (some bouncing, some spheres' masses from their density)
// falling onto them, a chain of balls on rods from a fixed point, and a plank on a hinge.
World machine_scene(int threads) {
  WorldSettings settings;
  settings.threads = threads;
  World world(settings);
  add_ground(world, 0.2, 0.6);
  for (int level = 0; level < 6; ++level) {
    add_box(world, Vec3(-3, 0.5 + level, 0), Vec3(0.5, 0.5, 0.5), 1.0);
    add_box(world, Vec3(3 + 0.04 * level, 0.4 + 0.8 * level, 0), Vec3(0.6, 0.4, 0.5), 2.0, tilt(0, 0.01 * level, 0.02));
  }
  for (int i = 0; i < 60; ++i) {
    const Vec3 position((i % 5) * 1.3 - 2.6 + 0.05 * (i % 3), 7 + 1.2 * (i / 5), ((i / 5) % 3) * 1.1 - 1.1);
    const Material material{i % 4 == 0 ? 0.6 : 0.1, 0.3 + 0.1 * (i % 4)};
    if (i % 3 == 0) {
      BodyDef sphere;
      sphere.name = "sphere";
      sphere.shape = Shape::sphere(0.3 + 0.05 * (i % 4));
      sphere.density = 500 + 100 * (i % 5);
      sphere.position = position;
      sphere.material = material;
      world.add_body(sphere);
    } else {
      add_box(world, position, Vec3(0.4, 0.3 + 0.05 * (i % 3), 0.35), 1.0 + 0.25 * (i % 5),
              tilt(0.1 * (i % 7), 0.2, 0.3 * (i % 2)), Vec3(0.2 * (i % 3) - 0.2, 0, 0), material);
    }
  }
  int previous = kWorld;
  for (int link = 0; link < 5; ++link) {
    const Vec3 at(6 + 0.4 * link, 6, 2), pivot = link == 0 ? Vec3(6, 6, 2) : Vec3(6 + 0.4 * (link - 1), 6, 2);
    const int ball = add_sphere(world, at + Vec3(0.4, 0, 0), 0.15, 0.5);
    JointDef rod;
    rod.type = JointType::distance;
    rod.body_a = previous;
    rod.body_b = ball;
    rod.anchor_a = link == 0 ? pivot : at;
    rod.anchor_b = at + Vec3(0.4, 0, 0);
    world.add_joint(rod);
    previous = ball;
  }
  const int plank = add_box(world, Vec3(-6, 3, 2), Vec3(1, 0.1, 0.3), 3.0);
  JointDef hinge;
  hinge.type = JointType::hinge;
  hinge.body_b = plank;
  hinge.anchor = Vec3(-7, 3, 2);
  hinge.axis = Vec3::UnitZ();
  world.add_joint(hinge);
  return world;
}

// What machine_scene's bodies are after 300 steps (5 s), on any x86-64 machine, with one thread
// or two.
constexpr uint64_t kMachineSceneHash = 0x60901a9ba8fe6b5f;

TEST(Determinism, OneHashOnEveryMachineWithOneThreadOrTwo) {
  for (const int threads : {1, 2}) {
    World world = machine_scene(threads);
    const uint64_t at_start = state_hash(world);
    size_t most_contacts = 0;
    for (int i = 0; i < 300; ++i) {
      world.step();
      most_contacts = std::max(most_contacts, world.record().contacts.size());
    }
    EXPECT_GT(most_contacts, 100u) << "the heap must land";
    EXPECT_NE(state_hash(world), at_start) << "nothing moved";
    EXPECT_EQ(hex(state_hash(world)), hex(kMachineSceneHash))
        << threads << " thread(s): the physics computes other bits than it did. If it changed on purpose, write the "
        << "new hash here in the same commit and say why (tests/README.md); if not, find what changed them.";
  }
}

World sphere_heap() {
  World world;
  add_ground(world, 0.2, 0.5);
  for (int i = 0; i < 60; ++i)
    add_sphere(world, Vec3((i % 4) * 0.45 - 0.7 + 0.01 * (i % 3), 0.5 + 0.55 * (i / 4), (i % 5) * 0.02), 0.2, 1.0 + 0.1 * (i % 7),
               Vec3(0.3 * ((i * 7) % 5 - 2), 0, 0.2 * ((i * 3) % 5 - 2)), {0.3, 0.5});
  return world;
}

// A heap big enough (several hundred manifolds) that the solver cuts it to several leaves and
// threads share the sweeps (joints would keep them on one thread); some bodies bounce, so
// restitution's time shifts run too.
World mixed_heap(int threads) {
  WorldSettings settings;
  settings.threads = threads;
  World world(settings);
  add_ground(world, 0.3, 0.6);
  for (int i = 0; i < 400; ++i) {
    const Vec3 position((i % 10) * 1.1 - 5 + 0.05 * (i % 3), 0.6 + 1.1 * (i / 100) + 0.3 * ((i / 10) % 2), ((i / 10) % 10) * 1.1 - 5);
    const Material material{i % 4 == 0 ? 0.5 : 0.0, 0.5};
    const Real turn = 0.05 * (i % 7);
    if (i % 3 == 0) add_sphere(world, position, 0.45, 1.0, Vec3::Zero(), material);
    else add_box(world, position, Vec3(0.45, 0.4, 0.35), 1.0, tilt(turn, 2 * turn, 3 * turn), Vec3::Zero(), material);
  }
  return world;
}

// What mixed_heap's bodies are after 150 steps (2.5 s: landed), on any x86-64 machine, with any thread count.
constexpr uint64_t kMixedHeapHash = 0x544410dc2df6ad3a;

// 1 to 8 threads, more than this machine's cores: the same bits (waits sleep when oversubscribed).
TEST(Determinism, AnyThreadCountGivesTheSameBits) {
  const std::vector<int> counts = {1, 2, 3, 4, 8};
  std::vector<World> worlds;
  for (const int threads : counts) worlds.push_back(mixed_heap(threads));
  size_t most_contacts = 0;
  for (int i = 0; i < 150; ++i)
    for (World& world : worlds) {
      world.step();
      most_contacts = std::max(most_contacts, world.record().contacts.size());
    }
  EXPECT_GT(most_contacts, 1000u) << "too few contacts for the sweeps to be shared";
  for (size_t k = 0; k < counts.size(); ++k)
    EXPECT_EQ(hex(state_hash(worlds[k])), hex(kMixedHeapHash)) << counts[k] << " threads; see OneHashOnEveryMachineWithOneThreadOrTwo";
  EXPECT_NE(state_hash(worlds[0]), state_hash(mixed_heap(1))) << "nothing moved";
}

TEST(Determinism, SameSceneTwiceIsBitIdenticalAfter600Steps) {
  World first = sphere_heap(), second = sphere_heap();
  for (int i = 0; i < 600; ++i) {
    first.step();
    second.step();
  }
  EXPECT_EQ(state_hash(first), state_hash(second));
  EXPECT_NE(state_hash(first), state_hash(sphere_heap())) << "nothing moved";
}

}  // namespace
}  // namespace impulse::physics
