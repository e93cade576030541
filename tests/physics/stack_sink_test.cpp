// How deep stacks sink into their soft contacts, and the sub-steps chosen from it
// (physics/stack_sink.h, WorldSettings::stack_sink): a box alone takes the fewest sub-steps, a
// taller tower more, each the fewest that keep its sinking within stack_sink; with stack_sink 0
// every step takes them all.
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

namespace impulse::physics {
namespace {

using namespace test;

struct Tower {
  int substeps = 0;  // in the last step
  Real sink = 0;     // m: how far the top box is below where rigid boxes would hold it
};

// `height` unit boxes stacked on the ground, left to settle for two seconds, sleeping off.
Tower settled_tower(int height, Real stack_sink) {
  WorldSettings settings;
  settings.sleep.enabled = false;
  settings.stack_sink = stack_sink;
  World world(settings);
  add_ground(world, 0, 0.6);
  int top = -1;
  for (int i = 0; i < height; ++i) top = add_box(world, Vec3(0, 0.5 + i, 0), Vec3(0.5, 0.5, 0.5), 1.0);
  for (int step = 0; step < 120; ++step) world.step();
  return {world.substeps(), Real(height - 0.5) - world.bodies()[top].position.y()};
}

TEST(StackSink, ABoxAloneTakesTheFewestSubsteps) {
  const Tower alone = settled_tower(1, WorldSettings{}.stack_sink);
  EXPECT_EQ(alone.substeps, WorldSettings{}.min_substeps);
}

TEST(StackSink, TallerTowersTakeMoreSubstepsAndSinkNoMoreThanAllowed) {
  const WorldSettings defaults;
  int previous = 0;
  for (const int height : {1, 5, 10, 20}) {
    const Tower tower = settled_tower(height, defaults.stack_sink);
    EXPECT_GE(tower.substeps, previous) << height << " boxes";
    EXPECT_LE(tower.substeps, defaults.substeps) << height << " boxes";
    EXPECT_LE(tower.sink, defaults.stack_sink) << height << " boxes, " << tower.substeps << " sub-steps";
    previous = tower.substeps;
  }
  EXPECT_GT(previous, defaults.min_substeps) << "20 boxes";
}

TEST(StackSink, ZeroAlwaysTakesEverySubstep) {
  EXPECT_EQ(settled_tower(1, 0).substeps, WorldSettings{}.substeps);
  EXPECT_EQ(settled_tower(20, 0).substeps, WorldSettings{}.substeps);
}

}  // namespace
}  // namespace impulse::physics
