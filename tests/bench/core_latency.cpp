#include "tests/bench/core_latency.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace impulse::bench {

namespace {

constexpr long kRoundTrips = 20000;
constexpr int kRounds = 3;
// A round ends after this long whatever it has done: on busy cores the partner may wait out a time
// slice for every pass, and the figure is then large, as it should be, without taking minutes.
constexpr auto kRoundBudget = std::chrono::milliseconds(30);
constexpr long kReleased = -1;  // the baton's value that sends the partner home

bool pin_to(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

// One round: this thread (pinned by the caller), a partner on `second`, passing a counter back and
// forth; nanoseconds per round trip.
double one_round_ns(int second) {
  alignas(64) std::atomic<long> baton{0};
  std::thread partner([&] {
    pin_to(second);
    for (long i = 0;; ++i) {
      long seen;
      while ((seen = baton.load(std::memory_order_acquire)) != 2 * i + 1)
        if (seen == kReleased) return;
      baton.store(2 * i + 2, std::memory_order_release);
    }
  });
  const auto start = std::chrono::steady_clock::now();
  long done = 0;
  for (; done < kRoundTrips; ++done) {
    if (done % 64 == 63 && std::chrono::steady_clock::now() - start > kRoundBudget) break;
    baton.store(2 * done + 1, std::memory_order_release);
    while (baton.load(std::memory_order_acquire) != 2 * done + 2) {
    }
  }
  const auto end = std::chrono::steady_clock::now();
  baton.store(kReleased, std::memory_order_release);
  partner.join();
  return std::chrono::duration<double, std::nano>(end - start).count() / double(std::max(done, 1L));
}

}  // namespace

double core_round_trip_ns() {
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return -1;
  std::vector<int> cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE && cpus.size() < 2; ++cpu)
    if (CPU_ISSET(cpu, &allowed)) cpus.push_back(cpu);
  if (cpus.size() < 2) return -1;
  double result = -1;
  // On a thread of its own, so that the caller's affinity is left as it was.
  std::thread([&] {
    if (!pin_to(cpus[0])) return;
    std::vector<double> rounds;
    for (int r = 0; r < kRounds; ++r) rounds.push_back(one_round_ns(cpus[1]));
    std::nth_element(rounds.begin(), rounds.begin() + kRounds / 2, rounds.end());
    result = rounds[kRounds / 2];
  }).join();
  return result;
}

}  // namespace impulse::bench
