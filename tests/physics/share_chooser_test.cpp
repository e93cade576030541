// Whether a step shares its work (physics/share_chooser.h): with an explicit thread count always;
// by default the way that has run faster, with the other way tried now and then, so that a machine
// that becomes busy (or quiet again) changes the choice within a few probes.
#include "physics/share_chooser.h"

#include <gtest/gtest.h>

namespace impulse::physics {
namespace {

// Runs `steps` steps at the given costs (s per unit of work) and counts the shared ones.
int shared_steps(ShareChooser& chooser, int steps, double alone_cost, double shared_cost) {
  int shared = 0;
  for (int step = 0; step < steps; ++step) {
    const bool shares = chooser.next_step_shares();
    shared += shares;
    chooser.step_took((shares ? shared_cost : alone_cost) * 1000, 1000);
  }
  return shared;
}

TEST(ShareChooser, AnExplicitThreadCountAlwaysShares) {
  ShareChooser chooser(false);
  EXPECT_EQ(shared_steps(chooser, 500, 1e-6, 1e-3), 500);
}

TEST(ShareChooser, TheFasterWayRunsAndTheOtherIsTriedNowAndThen) {
  ShareChooser chooser(true);
  // Quiet cores: sharing is faster; one step in 50 runs alone.
  const int quiet = shared_steps(chooser, 500, 2e-6, 1e-6);
  EXPECT_GE(quiet, 485);
  EXPECT_LT(quiet, 500) << "the other way is never tried";
  // Busy cores: sharing ten times slower. Within two probes (100 steps) the steps run alone.
  shared_steps(chooser, 100, 2e-6, 2e-5);
  EXPECT_LE(shared_steps(chooser, 500, 2e-6, 2e-5), 15);
  // Quiet again: back to sharing within a few probes.
  shared_steps(chooser, 200, 2e-6, 1e-6);
  EXPECT_GE(shared_steps(chooser, 500, 2e-6, 1e-6), 485);
}

TEST(ShareChooser, NearlyEqualWaysDoNotFlap) {
  ShareChooser chooser(true);
  EXPECT_GE(shared_steps(chooser, 1000, 1.0e-6, 1.1e-6), 970) << "sharing 10 % slower is not reason enough to switch";
}

}  // namespace
}  // namespace impulse::physics
