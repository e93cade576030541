// The contact finder (physics/contact_finder.h): the same contacts as colliding every pair, in order.
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
    finder.find(bodies, awake, dt, base_margin, team, threads, found);
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

// Contact recycling: what a fresh finder gives on the same bodies, after `finder` saw `before`.
struct TwoCalls {
  std::vector<Contact> recycled, fresh;
  size_t recycled_pairs = 0;
};
TwoCalls find_after(const std::vector<Body>& before, const std::vector<Body>& after, const std::vector<uint8_t>& awake, int threads) {
  const Real dt = 1.0 / 60, base_margin = 0.02;
  ThreadTeam team(threads);
  ContactFinder finder, fresh;
  TwoCalls out;
  finder.find(before, awake, dt, base_margin, team, threads, out.recycled);
  finder.find(after, awake, dt, base_margin, team, threads, out.recycled);
  out.recycled_pairs = finder.recycled_pairs();
  fresh.find(after, awake, dt, base_margin, team, threads, out.fresh);
  return out;
}

// Moved together, as one rigid body (turned and shifted), the bodies keep their relative poses:
// the pairs' contacts are recycled, carried by their body A, and agree with a fresh narrow phase
// but for rounding (the same pairs, points, normals and separations to 1e-9).
TEST(ContactFinder, BodiesMovedRigidlyKeepTheirContactsRecycled) {
  std::vector<uint8_t> awake;
  const auto before = random_bodies(5, awake);
  const Quat turn(Eigen::AngleAxis<Real>(0.3, Vec3(1, 2, 3).normalized()));
  const Vec3 shift(0.4, -0.2, 0.7);
  auto after = before;
  for (Body& body : after) {
    if (body.shape.type == ShapeType::plane) continue;  // planes are never recycled
    body.position = rotate(turn, body.position) + shift;
    body.orientation = (turn * body.orientation).normalized();
  }
  for (int threads : {1, 2, 3}) {
    const TwoCalls calls = find_after(before, after, awake, threads);
    EXPECT_GT(calls.recycled_pairs, 500u) << threads << " threads";
    ASSERT_EQ(calls.recycled.size(), calls.fresh.size()) << threads << " threads";
    for (size_t k = 0; k < calls.fresh.size(); ++k) {
      const Contact& r = calls.recycled[k];
      const Contact& f = calls.fresh[k];
      ASSERT_EQ(r.body_a, f.body_a) << k;
      ASSERT_EQ(r.body_b, f.body_b) << k;
      EXPECT_EQ(r.feature, f.feature) << k;
      EXPECT_LT((r.point - f.point).norm(), 1e-9) << k;
      EXPECT_LT((r.normal - f.normal).norm(), 1e-9) << k;
      EXPECT_NEAR(r.separation, f.separation, 1e-9) << k;
    }
  }
}

// Every moving body i shifted along x by i micrometres (each pair at least one apart, ten times
// what recycling allows): nothing is recycled, and the contacts are the fresh narrow phase's, bit
// for bit.
TEST(ContactFinder, PairsThatMovedAreBuiltAfresh) {
  std::vector<uint8_t> awake;
  const auto before = random_bodies(5, awake);
  auto after = before;
  for (size_t i = 0; i < after.size(); ++i)
    if (!after[i].is_static()) after[i].position.x() += 1e-6 * Real(i + 1);
  for (int threads : {1, 2}) {
    const TwoCalls calls = find_after(before, after, awake, threads);
    EXPECT_EQ(calls.recycled_pairs, 0u) << threads << " threads";
    ASSERT_EQ(calls.recycled.size(), calls.fresh.size()) << threads << " threads";
    for (size_t k = 0; k < calls.fresh.size(); ++k) {
      EXPECT_EQ(calls.recycled[k].point, calls.fresh[k].point) << k;
      EXPECT_EQ(calls.recycled[k].separation, calls.fresh[k].separation) << k;
      EXPECT_EQ(calls.recycled[k].feature, calls.fresh[k].feature) << k;
    }
  }
}

}  // namespace
}  // namespace impulse::physics
