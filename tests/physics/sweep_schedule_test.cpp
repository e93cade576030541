// The sweep's order and how two threads share it (physics/sweep_schedule.h): the order is the same
// for any thread count, and on two threads every body still receives its items in exactly that
// order, so the results keep their bits. Items solved side by side share no body.
#include "physics/sweep_schedule.h"
#include "physics/thread_team.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace impulse::physics {
namespace {

constexpr int kSide = 30;  // a kSide x kSide grid of bodies on the ground

// Contacts of a floor of boxes: each with its right and its far neighbour, and every third with
// the ground (-1, which never moves); sizes of one to four points, as manifolds have.
std::vector<SweepItem> floor_items() {
  std::vector<SweepItem> items;
  auto at = [](int body) { return Vec3(body % kSide, 0.5, body / kSide); };
  for (int body = 0; body < kSide * kSide; ++body) {
    const int x = body % kSide, z = body / kSide;
    if (x + 1 < kSide) items.push_back({body, body + 1, at(body), at(body + 1), 1 + body % 4});
    if (z + 1 < kSide) items.push_back({body, body + kSide, at(body), at(body + kSide), 2});
    if (body % 3 == 0) items.push_back({body, -1, at(body), Vec3::Zero(), 4});
  }
  return items;
}

// The items each body receives, in order, solving the places [place, place + width).
struct Received {
  const SweepSchedule& schedule;
  const std::vector<SweepItem>& items;
  std::vector<std::vector<int>> by_body = std::vector<std::vector<int>>(kSide * kSide);
  void operator()(int place, int width) {
    for (int k = 0; k < width; ++k) {
      const int item = schedule.order()[place + k];
      for (const int body : {items[item].a, items[item].b})
        if (body >= 0) by_body[body].push_back(item);  // only the thread the order lets at this body
    }
  }
};

TEST(SweepSchedule, TheOrderIsEveryItemOnceAndTheSameForAnyThreadCount) {
  const std::vector<SweepItem> items = floor_items();
  ASSERT_GT(items.size(), 1000u);  // large enough to be cut in two
  SweepSchedule one, two;
  one.plan(items, kSide * kSide, 1);
  two.plan(items, kSide * kSide, 2);
  EXPECT_FALSE(one.parallel());
  EXPECT_TRUE(two.parallel());
  EXPECT_EQ(one.order(), two.order());
  std::vector<int> sorted = one.order();
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], int(i));
}

TEST(SweepSchedule, OnTwoThreadsEveryBodyReceivesItsItemsInTheSweepsOrder) {
  const std::vector<SweepItem> items = floor_items();
  SweepSchedule serial, shared;
  serial.plan(items, kSide * kSide, 1);
  shared.plan(items, kSide * kSide, 2);
  Received expected{serial, items};
  for (int place = 0; place < int(serial.order().size()); ++place) expected(place, 1);
  ThreadTeam team(2);
  for (int sweep = 0; sweep < 20; ++sweep) {  // epochs: each sweep waits only for its own places
    Received received{shared, items};
    shared.sweep(team, received);
    ASSERT_EQ(received.by_body, expected.by_body) << "sweep " << sweep;
  }
}

TEST(SweepSchedule, ItemsSolvedSideBySideShareNoBodyAndHaveOneSize) {
  const std::vector<SweepItem> items = floor_items();
  for (const int threads : {1, 2}) {
    SweepSchedule schedule;
    schedule.plan(items, kSide * kSide, threads);
    int pairs = 0;
    for (int place = 0; place + 1 < int(schedule.order().size()); ++place) {
      if (!schedule.paired(place)) continue;
      ++pairs;
      const SweepItem& x = items[schedule.order()[place]];
      const SweepItem& y = items[schedule.order()[place + 1]];
      EXPECT_EQ(x.size, y.size);
      EXPECT_GT(x.size, 0);
      for (const int body : {x.a, x.b}) {
        if (body < 0) continue;
        EXPECT_TRUE(body != y.a && body != y.b) << "place " << place;
      }
      ++place;  // a pair is two places
    }
    EXPECT_GT(pairs, 100) << threads << " threads";
  }
}

TEST(SweepSchedule, SlotsAndBodiesAreInversePermutations) {
  const std::vector<SweepItem> items = floor_items();
  for (const int threads : {1, 2}) {
    SweepSchedule schedule;
    schedule.plan(items, kSide * kSide, threads);
    ASSERT_EQ(schedule.slots().size(), size_t(kSide * kSide));
    for (int body = 0; body < kSide * kSide; ++body) EXPECT_EQ(schedule.bodies()[schedule.slots()[body]], body);
    std::vector<int> seen(kSide * kSide, 0);
    ThreadTeam team(threads);
    schedule.for_each_slot(team, [&](int slot) { ++seen[slot]; });  // each slot once, whoever's
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), kSide * kSide) << threads << " threads";
  }
}

}  // namespace
}  // namespace impulse::physics
