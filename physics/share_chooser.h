// Whether a step shares its work among the thread team or runs on the caller alone. The results
// are the same either way (sweep_schedule.h), so with the default thread count (one per core) the
// world picks whichever is faster on this machine now: while other programs keep the cores busy,
// every meeting of the threads (a dozen a sub-step) can wait out a scheduler's time slice, and one
// thread alone has measured many times faster than two. Each step's wall time per unit of work is
// averaged for the way it ran; every kProbeEvery steps a probe runs kProbeSteps the other way, to
// keep that way's cost fresh; the faster way runs the others.
//
// Two things make a single step a poor witness, and the choice guards against both: a step can be
// preempted (one took 50 times its neighbours' time on quiet cores), so one step moves the chosen
// way's average by at most kChosenWeight of that average; and the first step of a way pays for the
// switch (sleeping threads woken, caches filled by the other core: sharing's first step after
// fifty alone measured 15 % slower than its warm ones), so a probe's first step is not counted.
#pragma once
#include <cstddef>

namespace impulse::physics {

class ShareChooser {
 public:
  explicit ShareChooser(bool adapts) : adapts_(adapts) {}
  // Whether the next step shares its work.
  bool next_step_shares();
  // The step just run took `seconds` for `work` (any measure proportional to its cost).
  void step_took(double seconds, double work);

  static constexpr int kProbeEvery = 100;
  static constexpr int kProbeSteps = 3;  // the first pays the switch; the others are measured

 private:
  bool adapts_;
  bool sharing_ = true;     // the way that has been faster
  bool this_step_shares_ = true;
  int steps_ = 0;
  int probe_step_ = -1;     // of the probe under way; -1: none
  double probe_sum_ = 0;    // its measured steps' costs
  double cost_[2] = {0, 0};  // seconds per unit of work, alone and shared; 0: not measured yet
};

}  // namespace impulse::physics
