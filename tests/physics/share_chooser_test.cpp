// Whether a step shares its work (physics/share_chooser.h): with an explicit thread count always;
// by default the way that has run faster, with the other way tried now and then, so that a machine
// that becomes busy (or quiet again) changes the choice within a few probes, and neither one
// preempted step nor the price of switching ways decides it.
#include "physics/share_chooser.h"

#include <gtest/gtest.h>

#include <functional>

namespace impulse::physics {
namespace {

constexpr int kEvery = ShareChooser::kProbeEvery;
constexpr int kProbe = ShareChooser::kProbeSteps;

// Cost of a step (s per unit of work): given whether it shares, whether the step before it did,
// and its number in the run.
using Cost = std::function<double(bool shares, bool before, int step)>;

Cost steady(double alone, double shared) {
  return [=](bool shares, bool, int) { return shares ? shared : alone; };
}

// Runs `steps` steps at the given costs and counts the shared ones.
int shared_steps(ShareChooser& chooser, int steps, const Cost& cost) {
  int shared = 0;
  bool before = true;
  for (int step = 0; step < steps; ++step) {
    const bool shares = chooser.next_step_shares();
    shared += shares;
    chooser.step_took(cost(shares, before, step) * 1000, 1000);
    before = shares;
  }
  return shared;
}

TEST(ShareChooser, AnExplicitThreadCountAlwaysShares) {
  ShareChooser chooser(false);
  EXPECT_EQ(shared_steps(chooser, 500, steady(1e-6, 1e-3)), 500);
}

TEST(ShareChooser, TheFasterWayRunsAndTheOtherIsTriedNowAndThen) {
  ShareChooser chooser(true);
  // Quiet cores: sharing is faster; a probe of kProbe steps alone every kEvery (and one at the start).
  const int probes = 1000 / kEvery + 1;
  const int quiet = shared_steps(chooser, 1000, steady(2e-6, 1e-6));
  EXPECT_GE(quiet, 1000 - probes * kProbe);
  EXPECT_LT(quiet, 1000) << "the other way is never tried";
  // Busy cores: sharing twenty times slower. Within a few steps they run alone, but for the probes.
  EXPECT_GE(shared_steps(chooser, 20, steady(2e-6, 4e-5)), 1);
  EXPECT_LE(shared_steps(chooser, 1000, steady(2e-6, 4e-5)), probes * kProbe);
  // Quiet again: back to sharing at the next probe.
  shared_steps(chooser, kEvery + kProbe, steady(2e-6, 1e-6));
  EXPECT_GE(shared_steps(chooser, 1000, steady(2e-6, 1e-6)), 1000 - probes * kProbe);
}

TEST(ShareChooser, NearlyEqualWaysDoNotFlap) {
  ShareChooser chooser(true);
  const int probes = 2000 / kEvery + 1;
  EXPECT_GE(shared_steps(chooser, 2000, steady(1.0e-6, 1.1e-6)), 2000 - probes * kProbe)
      << "sharing 10 % slower is not reason enough to switch";
}

// On quiet cores one shared step took 50 times its neighbours' time (the thread preempted): the
// old average, moved by a tenth of that step, made alone look cheaper, and the probes never won
// the way back.
TEST(ShareChooser, OnePreemptedStepDoesNotSwitch) {
  ShareChooser chooser(true);
  shared_steps(chooser, 500, steady(1.4e-6, 1e-6));
  const Cost hiccup = [](bool shares, bool, int step) { return shares ? (step == 0 ? 50e-6 : 1e-6) : 1.4e-6; };
  EXPECT_GE(shared_steps(chooser, 1000, hiccup), 1000 - (1000 / kEvery + 1) * kProbe);
}

// Sharing's first step after steps alone pays for waking the threads: 30 % over its warm steps.
// A probe that counted it would never bring back a way 30 % faster once it had left it.
TEST(ShareChooser, TheFirstStepOfAProbeIsNotCounted) {
  ShareChooser chooser(true);
  const Cost busy = steady(1.35e-6, 4e-5);
  shared_steps(chooser, 300, busy);
  EXPECT_LE(shared_steps(chooser, 1000, busy), (1000 / kEvery + 1) * kProbe);
  const Cost waking = [](bool shares, bool before, int) { return shares ? (before ? 1e-6 : 1.3e-6) : 1.35e-6; };
  shared_steps(chooser, kEvery + kProbe, waking);
  EXPECT_GE(shared_steps(chooser, 1000, waking), 1000 - (1000 / kEvery + 1) * kProbe);
}

}  // namespace
}  // namespace impulse::physics
