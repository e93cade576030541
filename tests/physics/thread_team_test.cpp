// The solver's thread team (physics/thread_team.h): every member runs each job once, the caller
// as member 0; run() returns only when all have finished; a barrier holds every member until all
// have reached it. Run under ThreadSanitizer too (scripts/test.sh).
#include "physics/thread_team.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace impulse::physics {
namespace {

TEST(ThreadTeam, EveryMemberRunsEachJobOnceAndRunWaitsForAll) {
  for (const int size : {1, 2, 3, 8}) {
    ThreadTeam team(size);
    ASSERT_EQ(team.size(), size);
    std::vector<int> runs(size, 0);  // each member writes only its own
    std::vector<std::thread::id> threads(size);
    for (int job = 0; job < 500; ++job)
      team.run([&](int member) {
        ++runs[member];
        threads[member] = std::this_thread::get_id();
      });
    // Read after run() returned: every write of every member is visible.
    for (int member = 0; member < size; ++member) EXPECT_EQ(runs[member], 500) << "member " << member << " of " << size;
    EXPECT_EQ(threads[0], std::this_thread::get_id()) << "member 0 is the caller";
    for (int member = 1; member < size; ++member) EXPECT_NE(threads[member], threads[0]) << "member " << member;
  }
}

TEST(ThreadTeam, ABarrierHoldsEveryMemberUntilAllHaveReachedIt) {
  for (const int size : {1, 2, 3, 8}) {
    ThreadTeam team(size);
    std::vector<int> first(size, 0), second(size, 0);
    std::atomic<int> missed{0};
    for (int round = 1; round <= 200; ++round)
      team.run([&](int member) {
        first[member] = round;
        team.barrier();
        for (int other = 0; other < size; ++other) missed += first[other] != round;
        second[member] = round;
        team.barrier();
        for (int other = 0; other < size; ++other) missed += second[other] != round;
      });
    EXPECT_EQ(missed.load(), 0) << size << " members";
  }
}

TEST(ThreadTeam, TheDefaultSizeIsOnePerCore) {
  EXPECT_EQ(ThreadTeam::default_size(), std::max(1, int(std::thread::hardware_concurrency())));
}

// A waiter sleeps once its spins are spent, and is woken by the raise it waits for, with more
// threads than cores too (each sleeps at once then).
TEST(WaitableCounter, AWaiterWakesForTheRaiseItWaitsFor) {
  for (const int threads : {1, 64}) {
    WaitableCounter counter;
    std::atomic<int> woken{0};
    std::thread waiter([&] {
      counter.wait_until_at_least(3, threads);
      woken = 1;
    });
    counter.raise(1);
    counter.raise(2);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // long past the spins: asleep
    EXPECT_EQ(woken.load(), 0) << "woke before its value";
    counter.raise(3);
    waiter.join();
    EXPECT_EQ(woken.load(), 1);
    EXPECT_EQ(counter.load(), 3u);
  }
}

}  // namespace
}  // namespace impulse::physics
