// Stacks that hold: towers of 10 and 20 boxes and pyramids of 21, 210 and 5050 stand still.
#include "physics/pyramid.h"
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

using namespace test;

const Vec3 kUnit(0.5, 0.5, 0.5);  // a unit box's half extents

// Stacks (exercise 3) with the default method and sleeping off: ../shared/bench/SCENES.md.
struct StackResult { Real top_drift = 0, any_drift = 0; };

StackResult run_stack(World& world, const std::vector<int>& boxes, int top, int steps) {
  std::vector<Vec3> start;
  for (int b : boxes) start.push_back(world.bodies()[b].position);
  StackResult result;
  for (int i = 0; i < steps; ++i) {
    world.step();
    result.top_drift = std::max(result.top_drift, (world.bodies()[top].position - start[top - boxes.front()]).norm());
  }
  for (size_t k = 0; k < boxes.size(); ++k)
    result.any_drift = std::max(result.any_drift, (world.bodies()[boxes[k]].position - start[k]).norm());
  return result;
}

WorldSettings no_sleep() {
  WorldSettings settings;
  settings.sleep.enabled = false;
  return settings;
}

class TowerStack : public ::testing::TestWithParam<int> {};

// The benchmark's stack-10 and stack-20 (friction 0.5, restitution 0, as Bullet's defaults).
TEST_P(TowerStack, StandsSixtySeconds) {
  World world(no_sleep());
  add_ground_box(world, {0, 0.5});
  std::vector<int> boxes;
  for (int i = 0; i < GetParam(); ++i) boxes.push_back(add_box(world, Vec3(0, 0.5 + i, 0), kUnit, 1.0, Quat::Identity(), Vec3::Zero(), {0, 0.5}));
  const StackResult r = run_stack(world, boxes, boxes.back(), 60 * 60);
  EXPECT_LT(r.top_drift, 0.01) << "m";
}

INSTANTIATE_TEST_SUITE_P(Stack, TowerStack, ::testing::Values(10, 20));

std::vector<int> add_pyramid(World& world, int base) {
  std::vector<int> boxes;
  for (const PyramidBox& box : pyramid_boxes(base)) boxes.push_back(add_box(world, box.centre, kUnit, 1.0));
  return boxes;
}

Real fastest_speed(const World& world, const std::vector<int>& boxes) {
  Real fastest = 0;
  for (int b : boxes) fastest = std::max(fastest, world.bodies()[b].velocity.norm());
  return fastest;
}

TEST(Stack, PyramidOf21BoxesStaysStill) {
  World world(no_sleep());
  add_ground_box(world);
  const std::vector<int> boxes = add_pyramid(world, 6);
  const StackResult r = run_stack(world, boxes, boxes.back(), 60 * 60);
  EXPECT_LT(r.top_drift, 0.002) << "m";
  EXPECT_LT(fastest_speed(world, boxes), 0.001) << "m/s";
}

// A wall one box thick is where too stiff contacts show first: at a quarter of the sub-step rate
// (Box2D's limit) this pyramid sways (kMaxHertzPerSubstepRate).
TEST(Stack, PyramidOf210BoxesStandsSixtySeconds) {
  World world(no_sleep());
  add_ground_box(world);
  const std::vector<int> boxes = add_pyramid(world, 20);
  ASSERT_EQ(boxes.size(), 210u);
  const StackResult r = run_stack(world, boxes, boxes.back(), 60 * 60);
  EXPECT_LT(r.top_drift, 0.01) << "m";
  EXPECT_LT(r.any_drift, 0.01) << "m";
  EXPECT_LT(fastest_speed(world, boxes), 0.001) << "m/s";
}

// "Stands its 500 steps": 100 rows of 120 Hz contacts sink the top by about 4.5 cm (0.45 mm a
// row, as the contact stiffness says), but nothing slides, tips or keeps moving.
TEST(Stack, LargePyramidOf5050BoxesStandsFiveHundredSteps) {
  World world(no_sleep());
  add_ground_box(world);
  const std::vector<int> boxes = add_pyramid(world, 100);
  ASSERT_EQ(boxes.size(), 5050u);
  const StackResult r = run_stack(world, boxes, boxes.back(), 500);
  EXPECT_LT(r.top_drift, 0.08) << "m";
  EXPECT_LT(r.any_drift, 0.08) << "m";
  EXPECT_LT(fastest_speed(world, boxes), 0.05) << "m/s";
}

}  // namespace
}  // namespace impulse::physics
