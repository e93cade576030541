// The caller and helper threads that run the solver's sweeps together. Every wait spins for a
// moment (the awaited work usually ends within microseconds), then sleeps on a futex until woken:
// with more threads than cores, a spinning waiter would take the core of the thread it waits for.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace impulse::physics {

// How long a waiter spins before it sleeps. Waking a sleeper costs tens of microseconds (a virtual
// machine's idle core may even be handed back to the host), more than most waits; but with more
// threads than cores every spin is taken from a thread that could be working.
class SpinBudget {
 public:
  explicit SpinBudget(int threads);
  // Spins once; false when the budget is spent and the caller should sleep.
  bool spin();

 private:
  int spins_ = 0;
  int spin_limit_;                                   // pauses before the clock is read, when oversubscribed
  std::chrono::steady_clock::time_point started_;    // at the 64th spin
};

// A counter that one thread raises and others wait on, spinning then sleeping (sweep_schedule.h's
// progress). raise() is a plain store unless somebody sleeps; a sleeper looks again every 200 µs.
class alignas(64) WaitableCounter {
 public:
  uint64_t load() const { return value_.load(std::memory_order_acquire); }
  void raise(uint64_t value);
  void wait_until_at_least(uint64_t target, int threads) const;

 private:
  std::atomic<uint64_t> value_{0};
  mutable std::atomic<uint32_t> sleepers_{0};
  mutable std::atomic<uint32_t> wakes_{0};  // 32 bits: a futex of its own to sleep on
};

class ThreadTeam {
 public:
  // `size` threads in all, the caller included: 1 runs every job on the caller alone.
  explicit ThreadTeam(int size);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return size_; }

  // Runs job(member) on every member, 0 on the caller, and returns when all have finished.
  void run(const std::function<void(int)>& job);
  // Inside a job: returns when every member has reached it.
  void barrier();

  // The solver's default: one per core (at least 1).
  static int default_size();

 private:
  void serve(int member);

  const int size_;  // set before the helpers start: they read it while helpers_ still grows
  std::vector<std::thread> helpers_;
  const std::function<void(int)>* job_ = nullptr;
  std::atomic<uint32_t> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stopping_{false};
  std::atomic<int> arrived_{0};
  std::atomic<uint32_t> barrier_phase_{0};
};

}  // namespace impulse::physics
