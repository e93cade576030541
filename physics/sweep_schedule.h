// The order of a Gauss-Seidel sweep over the manifolds, and how the threads of a ThreadTeam share
// it without changing a bit of the result.
//
// A large set is cut in two along its longest axis, and each half again, to a fixed number of
// levels (nested dissection: the world's one cut, up to 2^levels leaves). The order is the tree's, depth first: a node's crossing
// manifolds (those that join bodies on both sides of its cut), then its left subtree, then its
// right; in a leaf, last the manifolds that move a body of a crossing one. The tree depends on the
// bodies only, never on the thread count, so one thread and many give the same results. Threads
// take runs of leaves (each with the crossing manifolds of the subtrees it starts); before each
// manifold a thread waits until the manifolds before it in the order that move one of its bodies
// are done, so every body receives its impulses in exactly the sweep's order. Leaves touch
// different bodies, and a leaf's manifolds that wait for crossing ones come last: the threads
// hardly ever wait on each other. Threads beyond the leaves only meet at the barriers.
//
// Within each part, a manifold is followed where it can be by one a little further on with as many
// points that moves none of its bodies: the two are solved side by side (lanes.h).
#pragma once
#include "physics/math.h"
#include "physics/thread_team.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace impulse::physics {

// One constraint of the sweep: its two bodies (-1 for one that does not move), their positions, and
// its size (items of one size can be solved side by side; 0: never).
struct SweepItem {
  int a = -1, b = -1;
  Vec3 position_a = Vec3::Zero(), position_b = Vec3::Zero();
  int size = 0;
};

class SweepSchedule {
 public:
  // Orders the sweeps over `items` (given in their natural order), shares them among `threads`
  // and gives each of the `body_count` bodies its slot.
  // `levels` of cuts at most (up to 2^levels leaves, the most threads that share a sweep): fixed
  // for a world, whatever its thread count, as the order depends on it.
  void plan(const std::vector<SweepItem>& items, int body_count, int threads, int levels = kWorldLevels);
  // The world's: one cut, two leaves. Deeper cuts let up to eight threads share (3 levels, tested),
  // but cost two threads 10-15 % (the 210 pyramid, the heap of boxes): a subtree's first items wait
  // for the crossing ones above it, solved at the same moment by another thread. Ordering them last
  // in their subtree (not only in their leaf) is the next step; measured gains need more than the
  // two cores of these machines.
  static constexpr int kWorldLevels = 1;
  bool parallel() const { return lists_.size() > 1; }
  // Whether a place is solved side by side with the next.
  bool paired(int place) const { return paired_[place] != 0; }
  // The items in the sweeps' order; sweep() and the solver name them by their place in it.
  const std::vector<int>& order() const { return order_; }

  // Where each body's solver state goes: each thread's bodies together, so that no core's
  // prefetcher keeps pulling in lines that the other core is writing. The identity when serial.
  const std::vector<int>& slots() const { return slot_of_body_; }
  const std::vector<int>& bodies() const { return body_of_slot_; }

  // Sweeps take consecutive epochs; a thread's share of sweep `epoch` waits only for that sweep.
  uint64_t new_epochs(int count) {
    const uint64_t first = epoch_ + 1;
    epoch_ += uint64_t(count);
    return first;
  }
  // `thread`'s share of a sweep: solve(place, 1) for its places, in order, each once the places before
  // it that move the same bodies are done (on one thread: every place); solve(place, 2) for a place
  // paired with the next. Threads beyond the plan's do nothing.
  template <class Solve>
  void sweep_share(int thread, uint64_t epoch, Solve&& solve) const;
  // f(place) or f(slot) for `thread`'s places or bodies' slots, in any order.
  template <class F>
  void place_share(int thread, F&& f) const;
  template <class F>
  void slot_share(int thread, F&& f) const;

  // The whole sweep, or f for every place or slot, on the team (each thread its share).
  template <class Solve>
  void sweep(ThreadTeam& team, Solve&& solve) {
    const uint64_t epoch = new_epochs(1);
    run(team, [&](int thread) { sweep_share(thread, epoch, solve); });
  }
  template <class F>
  void for_each_place(ThreadTeam& team, F&& f) {
    run(team, [&](int thread) { place_share(thread, f); });
  }
  template <class F>
  void for_each_slot(ThreadTeam& team, F&& f) {
    run(team, [&](int thread) { slot_share(thread, f); });
  }
  // job(thread) on the team's threads, or on the caller alone when serial.
  template <class Job>
  void run(ThreadTeam& team, Job&& job) const {
    if (parallel()) team.run(job);
    else job(0);
  }

 private:
  void order_parts(const std::vector<SweepItem>& items, const std::vector<uint8_t>& part);
  void share(const std::vector<SweepItem>& items, const std::vector<uint8_t>& part, const std::vector<int>& thread_of_part,
             const std::vector<uint8_t>& is_crossing, int threads);
  void wait_for(int place, int thread, uint64_t epoch) const;

  // How far each thread has come in the current sweep (epoch * 2^32 + places done), raised only
  // after the places that another thread waits for.
  static constexpr int kEpochShift = 32;

  // Indexed by place (the position in the sweep's order):
  std::vector<int> order_;                // the item solved at each place
  std::vector<int> before_a_, before_b_;  // the last earlier place that moves the same body, or -1
  std::vector<uint8_t> owner_;            // the thread that solves it
  std::vector<uint32_t> rank_in_list_;    // its position in that thread's list
  std::vector<uint8_t> awaited_;          // whether another thread waits for it
  std::vector<uint8_t> paired_;           // whether it is solved side by side with the next
  std::vector<std::vector<int>> lists_;   // each thread's places, in order
  std::vector<int> slot_of_body_, body_of_slot_;
  std::vector<int> slot_begin_;           // thread t's slots are [slot_begin_[t], slot_begin_[t + 1])
  std::unique_ptr<WaitableCounter[]> progress_;
  int progress_count_ = 0;
  int team_size_ = 1;                     // how long a wait spins depends on it
  uint64_t epoch_ = 0;
};

template <class Solve>
void SweepSchedule::sweep_share(int thread, uint64_t epoch, Solve&& solve) const {
  if (!parallel()) {
    if (thread == 0)
      for (int place = 0; place < int(order_.size()); place += 1 + paired_[place]) solve(place, 1 + paired_[place]);
    return;
  }
  if (thread >= int(lists_.size())) return;
  const std::vector<int>& list = lists_[thread];
  for (size_t rank = 0; rank < list.size(); ++rank) {
    const int place = list[rank];
    const int width = 1 + paired_[place];  // a pair is one thread's, and next in its list
    for (int k = 0; k < width; ++k) {
      wait_for(before_a_[place + k], thread, epoch);
      wait_for(before_b_[place + k], thread, epoch);
    }
    solve(place, width);
    rank += width - 1;
    if (awaited_[place] || awaited_[place + width - 1]) progress_[thread].raise((epoch << kEpochShift) + rank + 1);
  }
}

template <class F>
void SweepSchedule::place_share(int thread, F&& f) const {
  if (!parallel()) {
    if (thread == 0)
      for (int place = 0; place < int(order_.size()); ++place) f(place);
    return;
  }
  if (thread < int(lists_.size()))
    for (int place : lists_[thread]) f(place);
}

template <class F>
void SweepSchedule::slot_share(int thread, F&& f) const {
  if (!parallel()) {
    if (thread == 0)
      for (int slot = 0; slot < int(slot_of_body_.size()); ++slot) f(slot);
    return;
  }
  if (thread + 1 < int(slot_begin_.size()))
    for (int slot = slot_begin_[thread]; slot < slot_begin_[thread + 1]; ++slot) f(slot);
}

}  // namespace impulse::physics
