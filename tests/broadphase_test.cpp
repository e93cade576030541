// Broad phase: exactly the overlapping pairs a brute-force search finds, in (i, j) order.
#include "physics/broadphase.h"
#include "physics/collide.h"
#include "physics/contact_finder.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace impulse::physics {
namespace {

// 500 boxes and spheres of mixed sizes, turned and moving at random in a 12 m cube (crowded
// enough for thousands of overlaps), some static, some asleep; and a ground plane.
std::vector<Body> random_bodies(unsigned seed, std::vector<uint8_t>& awake) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> unit(-1, 1), size(0.05, 0.8);
  std::vector<Body> bodies;
  BodyDef plane;
  plane.shape = Shape::plane(Vec3(0.1, 1, 0).normalized(), -3);
  bodies.push_back(make_body(plane));
  for (int i = 0; i < 500; ++i) {
    BodyDef def;
    def.shape = i % 3 == 0 ? Shape::sphere(size(rng)) : Shape::box(Vec3(size(rng), size(rng), size(rng)));
    def.position = Vec3(unit(rng), unit(rng), unit(rng)) * 6;
    def.orientation = Quat(unit(rng), unit(rng), unit(rng), unit(rng));
    def.is_static = i % 17 == 0;
    if (!def.is_static) {
      def.velocity = Vec3(unit(rng), unit(rng), unit(rng)) * 10;
      def.angular_velocity = Vec3(unit(rng), unit(rng), unit(rng)) * 5;
    }
    bodies.push_back(make_body(def));
  }
  awake.assign(bodies.size(), 0);
  for (size_t i = 0; i < bodies.size(); ++i) awake[i] = !bodies[i].is_static() && i % 11 != 0;
  return bodies;
}

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

// The contact finder gives what a loop over all pairs gives: same contacts, same order, same bits.
TEST(ContactFinder, SameContactsAsAllPairs) {
  std::vector<uint8_t> awake;
  const auto bodies = random_bodies(5, awake);
  const Real dt = 1.0 / 60, base_margin = 0.02;
  std::vector<Contact> expected;
  for (int i = 0; i < int(bodies.size()); ++i)
    for (int j = i + 1; j < int(bodies.size()); ++j)
      if (awake[i] || awake[j])
        collide(bodies[i], i, bodies[j], j, base_margin + motion_bound(bodies[i], dt) + motion_bound(bodies[j], dt), expected);
  ASSERT_GT(expected.size(), 500u);

  // However many threads share the narrow phase (each takes a run of pairs).
  for (int threads : {1, 2, 3}) {
    ThreadTeam team(threads);
    ContactFinder finder;
    std::vector<Contact> found;
    finder.find(bodies, awake, dt, base_margin, team, found);
    ASSERT_EQ(found.size(), expected.size()) << threads << " threads";
    for (size_t k = 0; k < found.size(); ++k) {
      EXPECT_EQ(found[k].body_a, expected[k].body_a) << k;
      EXPECT_EQ(found[k].body_b, expected[k].body_b) << k;
      EXPECT_EQ(found[k].feature, expected[k].feature) << k;
      EXPECT_EQ(found[k].point, expected[k].point) << k;
      EXPECT_EQ(found[k].normal, expected[k].normal) << k;
      EXPECT_EQ(found[k].separation, expected[k].separation) << k;
    }
  }
}

}  // namespace
}  // namespace impulse::physics
