#include "physics/thread_team.h"

#include <algorithm>
#include <chrono>

namespace impulse::physics {

namespace {

inline void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

using Clock = std::chrono::steady_clock;

// A helper idle this long goes to sleep; waking it again costs tens of microseconds (a virtual
// machine's idle core may even be handed back to the host), more than most pauses between jobs.
constexpr auto kSpinBeforeSleep = std::chrono::microseconds(300);
// A waiting thread yields its core only after this long: whoever it waits for may need it.
constexpr auto kSpinBeforeYield = std::chrono::microseconds(50);

}  // namespace

void Backoff::pause() {
  cpu_pause();
  if (++spins_ % 64 != 0) return;  // the clock is read now and then only
  if (spins_ == 64) started_ = Clock::now();
  else if (Clock::now() - started_ > kSpinBeforeYield) std::this_thread::yield();
}

ThreadTeam::ThreadTeam(int size) {
  for (int member = 1; member < size; ++member) helpers_.emplace_back([this, member] { serve(member); });
}

ThreadTeam::~ThreadTeam() {
  stopping_.store(true, std::memory_order_release);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& helper : helpers_) helper.join();
}

// The sweeps are shared in two (sweep_schedule.h): more threads would only wait.
int ThreadTeam::default_size() { return std::clamp(int(std::thread::hardware_concurrency()), 1, 2); }

void ThreadTeam::run(const std::function<void(int)>& job) {
  if (helpers_.empty()) {
    job(0);
    return;
  }
  job_ = &job;
  pending_.store(int(helpers_.size()), std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  job(0);
  Backoff backoff;
  while (pending_.load(std::memory_order_acquire) != 0) backoff.pause();
}

void ThreadTeam::barrier() {
  if (helpers_.empty()) return;
  const uint32_t phase = barrier_phase_.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == size()) {
    arrived_.store(0, std::memory_order_relaxed);
    barrier_phase_.store(phase + 1, std::memory_order_release);
    return;
  }
  Backoff backoff;
  while (barrier_phase_.load(std::memory_order_acquire) == phase) backoff.pause();
}

void ThreadTeam::serve(int member) {
  uint32_t seen = 0;
  for (;;) {
    int spins = 0;
    Clock::time_point idle_since;
    uint32_t generation;
    while ((generation = generation_.load(std::memory_order_acquire)) == seen) {
      cpu_pause();
      if (++spins % 64 != 0) continue;
      if (spins == 64) idle_since = Clock::now();
      else if (Clock::now() - idle_since > kSpinBeforeSleep) generation_.wait(seen, std::memory_order_acquire);
    }
    seen = generation;
    if (stopping_.load(std::memory_order_acquire)) return;
    (*job_)(member);
    pending_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

}  // namespace impulse::physics
