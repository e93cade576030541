#include "physics/share_chooser.h"

#include <algorithm>

namespace impulse::physics {

namespace {

constexpr double kChosenWeight = 0.1;  // of the latest step, in the chosen way's average, which one
                                       // step can raise by at most this fraction
// The other way's cost is its latest probe: probes are rare, and the machine may have changed
// since the one before. A lucky probe costs a few steps the wrong way: the chosen way's average
// soon shows it, against the old way's, which stands.
constexpr double kSwitchBelow = 0.8;   // the other way must be this much cheaper: no flapping

}  // namespace

bool ShareChooser::next_step_shares() {
  if (!adapts_) return true;
  ++steps_;
  // The other way's first probe comes early (from the second step), then one every kProbeEvery.
  if (probe_step_ < 0 && (steps_ % kProbeEvery == 0 || (steps_ == 2 && cost_[!sharing_] == 0))) {
    probe_step_ = 0;
    probe_sum_ = 0;
  }
  this_step_shares_ = probe_step_ >= 0 ? !sharing_ : sharing_;
  return this_step_shares_;
}

void ShareChooser::step_took(double seconds, double work) {
  if (!adapts_ || !(work > 0)) return;
  const double unit = seconds / work;
  if (probe_step_ >= 0) {
    if (probe_step_ > 0) probe_sum_ += unit;
    if (++probe_step_ < kProbeSteps) return;
    probe_step_ = -1;
    cost_[!sharing_] = probe_sum_ / (kProbeSteps - 1);
  } else {
    double& cost = cost_[sharing_];
    cost = cost == 0 ? unit : cost + kChosenWeight * (std::min(unit, 2 * cost) - cost);
  }
  const double other = cost_[!sharing_];
  if (other > 0 && other < kSwitchBelow * cost_[sharing_]) sharing_ = !sharing_;
}

}  // namespace impulse::physics
