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

}  // namespace
}  // namespace impulse::physics
