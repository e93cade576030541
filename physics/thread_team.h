// The caller and a few helper threads that run the solver's sweeps together. A helper spins for a
// moment after each job (the next sweep comes within microseconds), then sleeps until woken.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace impulse::physics {

// Spins politely: a pause instruction, and a yield now and then so that a thread we wait for can
// run even when there are more threads than cores.
class Backoff {
 public:
  void pause();

 private:
  int spins_ = 0;
  std::chrono::steady_clock::time_point started_;  // at the 64th spin
};

class ThreadTeam {
 public:
  // `size` threads in all, the caller included: 1 runs every job on the caller alone.
  explicit ThreadTeam(int size);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return int(helpers_.size()) + 1; }

  // Runs job(member) on every member, 0 on the caller, and returns when all have finished.
  void run(const std::function<void(int)>& job);
  // Inside a job: returns when every member has reached it.
  void barrier();

  // The solver's default: one per core, at least 1 and at most 2.
  static int default_size();

 private:
  void serve(int member);

  std::vector<std::thread> helpers_;
  const std::function<void(int)>* job_ = nullptr;
  std::atomic<uint32_t> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stopping_{false};
  std::atomic<int> arrived_{0};
  std::atomic<uint32_t> barrier_phase_{0};
};

}  // namespace impulse::physics
