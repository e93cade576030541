// The solver's thread team (physics/thread_team.h): every member runs each job once, the caller
// as member 0; run() returns only when all have finished; a barrier holds every member until all
// have reached it. Run under ThreadSanitizer too (scripts/test.sh).
#include "physics/thread_team.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace impulse::physics {
namespace {

TEST(ThreadTeam, EveryMemberRunsEachJobOnceAndRunWaitsForAll) {
  for (const int size : {1, 2, 3}) {
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
  for (const int size : {1, 2, 3}) {
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

TEST(ThreadTeam, TheDefaultSizeIsOneOrTwo) {
  EXPECT_GE(ThreadTeam::default_size(), 1);
  EXPECT_LE(ThreadTeam::default_size(), 2);
}

}  // namespace
}  // namespace impulse::physics
