// Whether a step shares its work among the thread team or runs on the caller alone. The results
// are the same either way (sweep_schedule.h), so with the default thread count (one per core) the
// world picks whichever is faster on this machine now: while other programs keep the cores busy,
// every meeting of the threads (a dozen a sub-step) can wait out a scheduler's time slice, and one
// thread alone has measured many times faster than two. Each step's wall time per unit of work is
// averaged for the way it ran; every kProbeEvery-th step runs the other way, to keep that way's
// average fresh; the faster way runs the others. An explicit thread count always shares.
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

 private:
  static constexpr int kProbeEvery = 50;
  bool adapts_;
  bool sharing_ = true;     // the way that has been faster
  bool this_step_shares_ = true;
  int steps_ = 0;
  double cost_[2] = {0, 0};  // seconds per unit of work, alone and shared; 0: not measured yet
};

}  // namespace impulse::physics
