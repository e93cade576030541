// The sweep's order and how threads share it (physics/sweep_schedule.h): the order is the same for
// any thread count, and on any number of threads every body still receives its items in exactly
// that order, so the results keep their bits. Items solved side by side share no body.
#include "physics/sweep_schedule.h"
#include "physics/thread_team.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace impulse::physics {
namespace {

constexpr int kSide = 30;  // a kSide x kSide grid of bodies on the ground
constexpr int kLevels = 3;  // cut to eight leaves (the world cuts once: SweepSchedule::kWorldLevels)

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
  ASSERT_GT(items.size(), 2000u);  // large enough to be cut to eight leaves
  SweepSchedule one;
  one.plan(items, kSide * kSide, 1, kLevels);
  EXPECT_FALSE(one.parallel());
  std::vector<int> sorted = one.order();
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], int(i));
  for (const int threads : {2, 3, 4, 8, 12}) {
    SweepSchedule shared;
    shared.plan(items, kSide * kSide, threads, kLevels);
    EXPECT_TRUE(shared.parallel()) << threads << " threads";
    EXPECT_EQ(one.order(), shared.order()) << threads << " threads";
  }
}

TEST(SweepSchedule, OnAnyThreadCountEveryBodyReceivesItsItemsInTheSweepsOrder) {
  const std::vector<SweepItem> items = floor_items();
  SweepSchedule serial;
  serial.plan(items, kSide * kSide, 1, kLevels);
  Received expected{serial, items};
  for (int place = 0; place < int(serial.order().size()); ++place) expected(place, 1);
  for (const int threads : {2, 3, 4, 8}) {  // more than this machine's cores: waits sleep
    SweepSchedule shared;
    shared.plan(items, kSide * kSide, threads, kLevels);
    ThreadTeam team(threads);
    for (int sweep = 0; sweep < 20; ++sweep) {  // epochs: each sweep waits only for its own places
      Received received{shared, items};
      shared.sweep(team, received);
      ASSERT_EQ(received.by_body, expected.by_body) << threads << " threads, sweep " << sweep;
    }
  }
}

// Up to eight threads each sweep a share, none less than half an even share.
TEST(SweepSchedule, EveryThreadUpToEightSweepsAFairShare) {
  const std::vector<SweepItem> items = floor_items();
  for (const int threads : {2, 3, 4, 8}) {
    SweepSchedule schedule;
    schedule.plan(items, kSide * kSide, threads, kLevels);
    std::vector<int> places(threads, 0);  // each thread counts only its own
    ThreadTeam team(threads);
    const uint64_t epoch = schedule.new_epochs(1);
    team.run([&](int thread) { schedule.sweep_share(thread, epoch, [&](int, int width) { places[thread] += width; }); });
    for (int thread = 0; thread < threads; ++thread)
      EXPECT_GE(places[thread], int(items.size()) / threads / 2) << "thread " << thread << " of " << threads;
  }
}

TEST(SweepSchedule, ItemsSolvedSideBySideShareNoBodyAndHaveOneSize) {
  const std::vector<SweepItem> items = floor_items();
  for (const int threads : {1, 2}) {
    SweepSchedule schedule;
    schedule.plan(items, kSide * kSide, threads, kLevels);
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
  for (const int threads : {1, 2, 3, 8}) {
    SweepSchedule schedule;
    schedule.plan(items, kSide * kSide, threads, kLevels);
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
