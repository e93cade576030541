#include "physics/thread_team.h"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <ctime>

namespace impulse::physics {

namespace {

inline void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

using Clock = std::chrono::steady_clock;

// With a core each, a waiter spins this long before it sleeps: most waits are shorter.
constexpr auto kSpinBeforeSleep = std::chrono::microseconds(300);
// With more threads than cores, a few pauses only: the awaited thread may need this core.
constexpr int kOversubscribedSpins = 256;
// The longest a WaitableCounter's waiter sleeps before it looks again (a raise may miss it).
constexpr std::chrono::nanoseconds kSleepSlice = std::chrono::microseconds(200);

// Read once: std::thread::hardware_concurrency() reads a file of /sys at each call.
int hardware_threads() {
  static const int threads = std::max(1, int(std::thread::hardware_concurrency()));
  return threads;
}

// Spins while `value` holds `old`, then sleeps on it until it changes.
template <class T>
void wait_while_equal(const std::atomic<T>& value, T old, int threads) {
  SpinBudget budget(threads);
  while (value.load(std::memory_order_acquire) == old)
    if (!budget.spin()) value.wait(old, std::memory_order_acquire);
}

}  // namespace

SpinBudget::SpinBudget(int threads) : spin_limit_(threads > hardware_threads() ? kOversubscribedSpins : 0) {}

bool SpinBudget::spin() {
  cpu_pause();
  ++spins_;
  if (spin_limit_ > 0) return spins_ < spin_limit_;
  if (spins_ % 64 != 0) return true;  // the clock is read now and then only
  if (spins_ == 64) started_ = Clock::now();
  return Clock::now() - started_ < kSpinBeforeSleep;
}

// The raise is a plain release store, and the check for sleepers a plain load: a full fence
// between them (what makes Dekker's pattern exact) cost the 210 pyramid's step 5-10 %, as each
// sweep raises tens of times. So a raise can miss a waiter that is just going to sleep; that
// waiter sleeps at most kSleepSlice before it looks again.
void WaitableCounter::raise(uint64_t value) {
  value_.store(value, std::memory_order_release);
  if (sleepers_.load(std::memory_order_relaxed) == 0) return;
  wakes_.fetch_add(1, std::memory_order_release);
  syscall(SYS_futex, reinterpret_cast<uint32_t*>(&wakes_), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
}

void WaitableCounter::wait_until_at_least(uint64_t target, int threads) const {
  if (value_.load(std::memory_order_acquire) >= target) return;  // most often: no wait at all
  SpinBudget budget(threads);
  while (value_.load(std::memory_order_acquire) < target)
    if (!budget.spin()) break;
  if (value_.load(std::memory_order_acquire) >= target) return;
  sleepers_.fetch_add(1, std::memory_order_seq_cst);
  for (;;) {
    const uint32_t wakes = wakes_.load(std::memory_order_acquire);
    if (value_.load(std::memory_order_acquire) >= target) break;
    timespec slice{0, kSleepSlice.count()};
    syscall(SYS_futex, reinterpret_cast<uint32_t*>(&wakes_), FUTEX_WAIT_PRIVATE, wakes, &slice, nullptr, 0);
  }
  sleepers_.fetch_sub(1, std::memory_order_relaxed);
}

ThreadTeam::ThreadTeam(int size) : size_(std::max(size, 1)) {
  for (int member = 1; member < size; ++member) helpers_.emplace_back([this, member] { serve(member); });
}

ThreadTeam::~ThreadTeam() {
  stopping_.store(true, std::memory_order_release);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& helper : helpers_) helper.join();
}

int ThreadTeam::default_size() { return hardware_threads(); }

void ThreadTeam::run(const std::function<void(int)>& job) {
  if (size_ == 1) {
    job(0);
    return;
  }
  job_ = &job;
  pending_.store(size_ - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  job(0);
  for (int left; (left = pending_.load(std::memory_order_acquire)) != 0;) wait_while_equal(pending_, left, size());
}

void ThreadTeam::barrier() {
  if (size_ == 1) return;
  const uint32_t phase = barrier_phase_.load(std::memory_order_acquire);
  if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == size()) {
    arrived_.store(0, std::memory_order_relaxed);
    barrier_phase_.store(phase + 1, std::memory_order_release);
    barrier_phase_.notify_all();
    return;
  }
  wait_while_equal(barrier_phase_, phase, size());
}

void ThreadTeam::serve(int member) {
  uint32_t seen = 0;
  for (;;) {
    wait_while_equal(generation_, seen, size());
    seen = generation_.load(std::memory_order_acquire);
    if (stopping_.load(std::memory_order_acquire)) return;
    (*job_)(member);
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_all();
  }
}

}  // namespace impulse::physics
