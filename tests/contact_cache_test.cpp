// The contact cache: kept contacts move with their bodies and measure their separations anew; a
// pair that moved more than the tolerance is asked anew, and then gets exactly collide_boxes()'s.
#include "physics/collide.h"
#include "physics/contact_cache.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace impulse::physics {
namespace {

constexpr Real kMargin = 0.02;

Body box(const Vec3& half, const Vec3& position, const Quat& orientation = Quat::Identity()) {
  BodyDef def;
  def.shape = Shape::box(half);
  def.position = position;
  def.orientation = orientation;
  return make_body(def);
}

Quat about_y(Real degrees) { return Quat(Eigen::AngleAxis<Real>(degrees * std::numbers::pi / 180, Vec3::UnitY())); }

std::vector<Contact> through_cache(ContactCache& cache, const Body& a, const Body& b) {
  std::vector<Contact> out;
  cache.begin(1);
  cache.collide_boxes(a, 0, b, 1, kMargin, 0, out);
  cache.end();
  return out;
}

std::vector<Contact> fresh_within(const Body& a, const Body& b, Real margin) {
  std::vector<Contact> out;
  collide_boxes(a, 0, b, 1, margin, out);
  return out;
}

std::vector<Contact> fresh(const Body& a, const Body& b) { return fresh_within(a, b, kMargin); }

// A unit box turned 30 degrees, 1 mm into a larger box: its four bottom corners.
struct Resting : ::testing::Test {
  Body lower = box(Vec3(2, 0.5, 2), Vec3(0, 0, 0));
  Body upper = box(Vec3(0.5, 0.5, 0.5), Vec3(0.1, 0.999, -0.2), about_y(30));
};

TEST_F(Resting, KeptContactsMoveWithTheBodiesAndMeasureTheirSeparationsAnew) {
  ContactCache cache;
  ASSERT_EQ(through_cache(cache, lower, upper).size(), 4u);
  // A small slide and sink, and both bodies turned together: within the tolerance.
  const Quat turn(Eigen::AngleAxis<Real>(0.3, Vec3(1, 2, 3).normalized()));
  upper.position += Vec3(0.1e-3, -0.2e-3, 0.15e-3);
  for (Body* body : {&lower, &upper}) {
    body->position = turn * body->position;
    body->orientation = turn * body->orientation;
  }
  const std::vector<Contact> kept = through_cache(cache, lower, upper), expected = fresh(lower, upper);
  ASSERT_EQ(kept.size(), expected.size());
  for (size_t k = 0; k < kept.size(); ++k) {
    EXPECT_EQ(kept[k].feature, expected[k].feature) << k;
    EXPECT_NEAR(kept[k].separation, expected[k].separation, 1e-12) << k;  // a face's plane: exact
    EXPECT_LT((kept[k].normal - expected[k].normal).norm(), 1e-12) << k;
    EXPECT_LT((kept[k].point - expected[k].point).norm(), 0.2e-3) << k;  // by half the slide at most
  }
}

TEST_F(Resting, PairsThatMovedMoreAreAskedAnew) {
  ContactCache cache;
  through_cache(cache, lower, upper);
  upper.position.x() += 2e-3;  // beyond the tolerance: a slide
  std::vector<Contact> kept = through_cache(cache, lower, upper), expected = fresh(lower, upper);
  ASSERT_EQ(kept.size(), expected.size());
  for (size_t k = 0; k < kept.size(); ++k) EXPECT_EQ(kept[k].point, expected[k].point) << k;
  upper.orientation = about_y(30.1);  // beyond the tolerance: a turn
  kept = through_cache(cache, lower, upper);
  expected = fresh(lower, upper);
  ASSERT_EQ(kept.size(), expected.size());
  for (size_t k = 0; k < kept.size(); ++k) EXPECT_EQ(kept[k].point, expected[k].point) << k;
}

TEST_F(Resting, APointThatLeavesTheMarginIsNotKept) {
  ContactCache cache;
  through_cache(cache, lower, upper);
  lower.position.y() -= 0.4e-3;  // within the tolerance, but the corners now 0.6 mm deep ...
  std::vector<Contact> out;
  cache.begin(1);
  cache.collide_boxes(lower, 0, upper, 1, -0.8e-3, 0, out);  // ... where only deeper ones count
  cache.end();
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(fresh_within(lower, upper, -0.8e-3).empty());
}

}  // namespace
}  // namespace impulse::physics
