// Broad phase: exactly the overlapping pairs a brute-force search finds, in (i, j) order.
#include "physics/broadphase.h"
#include "physics/collide.h"
#include "physics/contact_finder.h"
#include "tests/physics/random_bodies.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace impulse::physics {
namespace {

using test::random_bodies;

TEST(BroadPhase, FindsExactlyTheBruteForcePairsInOrder) {
  for (unsigned seed : {1u, 2u, 3u}) {
    std::vector<uint8_t> awake;
    const auto bodies = random_bodies(seed, awake);
    std::vector<Aabb> boxes;
    for (const Body& body : bodies) boxes.push_back(body_aabb(body, 0.01 + motion_bound(body, 1.0 / 60)));

    std::vector<BodyPair> expected;
    for (int i = 0; i < int(boxes.size()); ++i)
      for (int j = i + 1; j < int(boxes.size()); ++j)
        if ((awake[i] || awake[j]) && overlap(boxes[i], boxes[j])) expected.push_back({i, j});
    ASSERT_GT(expected.size(), 1000u) << "the scene should be crowded";

    BroadPhase broad_phase;
    std::vector<BodyPair> pairs;
    broad_phase.find_pairs(boxes, awake, pairs);
    EXPECT_EQ(pairs, expected) << "seed " << seed;
    broad_phase.find_pairs(boxes, awake, pairs);  // again, with its buffers in use
    EXPECT_EQ(pairs, expected) << "seed " << seed << ", second call";
    ThreadTeam team(2);
    broad_phase.find_pairs(boxes, awake, pairs, &team);  // two threads sweeping
    EXPECT_EQ(pairs, expected) << "seed " << seed << ", two threads";
  }
}

// From one call to the next the bodies move: the order kept from the last call is sorted anew,
// by a few moves when they moved a little, and from scratch when they scattered.
TEST(BroadPhase, FindsTheBruteForcePairsAfterTheBodiesMove) {
  std::vector<uint8_t> awake;
  auto bodies = random_bodies(5, awake);
  BroadPhase broad_phase;
  ThreadTeam team(2);
  std::mt19937 rng(5);
  for (Real reach : {0.05, 0.05, 3.0, 0.05}) {
    std::uniform_real_distribution<Real> shift(-reach, reach);
    for (Body& body : bodies)
      if (!body.is_static()) body.position += Vec3(shift(rng), shift(rng), shift(rng));
    std::vector<Aabb> boxes;
    for (const Body& body : bodies) boxes.push_back(body_aabb(body, 0.01));
    std::vector<BodyPair> expected, pairs;
    for (int i = 0; i < int(boxes.size()); ++i)
      for (int j = i + 1; j < int(boxes.size()); ++j)
        if ((awake[i] || awake[j]) && overlap(boxes[i], boxes[j])) expected.push_back({i, j});
    broad_phase.find_pairs(boxes, awake, pairs, &team);
    EXPECT_EQ(pairs, expected) << "bodies moved up to " << reach << " m";
  }
}

TEST(BroadPhase, PlanePairsWithEveryAwakeBodyOnly) {
  std::vector<uint8_t> awake;
  const auto bodies = random_bodies(4, awake);
  std::vector<Aabb> boxes;
  for (const Body& body : bodies) boxes.push_back(body_aabb(body, 0.01));
  std::vector<BodyPair> pairs;
  BroadPhase().find_pairs(boxes, awake, pairs);
  size_t with_plane = 0, awake_count = 0;
  for (const BodyPair& p : pairs) with_plane += p.a == 0;
  for (size_t i = 1; i < awake.size(); ++i) awake_count += awake[i];
  EXPECT_EQ(with_plane, awake_count);
}

TEST(BroadPhase, FlatLayerAndTinyInputs) {
  BroadPhase broad_phase;
  std::vector<BodyPair> pairs;
  broad_phase.find_pairs({}, {}, pairs);
  EXPECT_TRUE(pairs.empty());
  // A row of touching unit boxes, all at the same height and depth: only neighbours pair.
  std::vector<Aabb> row;
  for (int i = 0; i < 50; ++i) row.push_back({Vec3(i, 0, 0), Vec3(i + 1, 1, 1)});
  broad_phase.find_pairs(row, std::vector<uint8_t>(50, 1), pairs);
  ASSERT_EQ(pairs.size(), 49u);
  for (int i = 0; i < 49; ++i) EXPECT_EQ(pairs[i], (BodyPair{i, i + 1}));
}

}  // namespace
}  // namespace impulse::physics
