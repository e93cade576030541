#include "physics/share_chooser.h"

namespace impulse::physics {

namespace {

constexpr double kChosenWeight = 0.1;  // of the latest step, in the chosen way's average
// The other way's cost is its latest probe: probes are rare, and the machine may have changed
// since the one before. A lucky probe costs a few steps the wrong way: the chosen way's average
// soon shows it, against the old way's, which stands.
constexpr double kSwitchBelow = 0.8;   // the other way must be this much cheaper: no flapping

}  // namespace

bool ShareChooser::next_step_shares() {
  if (!adapts_) return true;
  ++steps_;
  // The other way's first sample comes early (the second step), then one every kProbeEvery.
  const bool probe = steps_ % kProbeEvery == 0 || (steps_ == 2 && cost_[!sharing_] == 0);
  this_step_shares_ = probe ? !sharing_ : sharing_;
  return this_step_shares_;
}

void ShareChooser::step_took(double seconds, double work) {
  if (!adapts_ || !(work > 0)) return;
  const double unit = seconds / work;
  double& cost = cost_[this_step_shares_];
  cost = cost == 0 || this_step_shares_ != sharing_ ? unit : cost + kChosenWeight * (unit - cost);
  const double other = cost_[!sharing_];
  if (other > 0 && other < kSwitchBelow * cost_[sharing_]) sharing_ = !sharing_;
}

}  // namespace impulse::physics
