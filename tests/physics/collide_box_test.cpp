// Narrow phase against a box's faces (physics/collide_box.cpp): a box on a plane, a sphere on a
// box; contact points, normals and depths.
#include "physics/collide.h"
#include "physics/manifold.h"
#include "tests/physics/collide_bodies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace impulse::physics {
namespace {

using namespace test;

// --- box against plane -------------------------------------------------------------------------

TEST(BoxPlane, RestingUnitBoxTouchesAtItsFourBottomCorners) {
  const Body box = unit_box(Vec3(1, 0.5, -2));
  const Body ground = make(Shape::plane(Vec3::UnitY(), 0), Vec3::Zero());
  const auto cs = contacts(ground, box);  // swapped: the box becomes A
  ASSERT_EQ(cs.size(), 4u);
  std::vector<Vec3> expected{{0.5, 0, -2.5}, {1.5, 0, -2.5}, {0.5, 0, -1.5}, {1.5, 0, -1.5}};
  for (size_t k = 0; k < cs.size(); ++k) {
    EXPECT_EQ(cs[k].body_a, 1);
    EXPECT_EQ(cs[k].body_b, 0);
    expect_near(cs[k].normal, Vec3::UnitY(), kTol, "normal");
    EXPECT_NEAR(cs[k].separation, 0, kTol);
    expect_near(cs[k].point, expected[k], kTol, "corner");
  }
  EXPECT_EQ(features(cs), (std::vector<uint32_t>{0, 1, 4, 5}));
}

TEST(BoxPlane, SpeculativeWithinMarginNothingBeyond) {
  const Body ground = make(Shape::plane(Vec3::UnitY(), 0), Vec3::Zero());
  const auto near = contacts(unit_box(Vec3(0, 0.51, 0)), ground);
  ASSERT_EQ(near.size(), 4u);
  for (const Contact& c : near) EXPECT_NEAR(c.separation, 0.01, kTol);
  EXPECT_TRUE(contacts(unit_box(Vec3(0, 0.53, 0)), ground).empty());
}

TEST(BoxPlane, BoxTiltedAboutZTouchesAlongItsLowestEdge) {
  const Real c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Real reach = 0.5 * (c + s);  // lowest corner below the centre
  const Body box = unit_box(Vec3(0, reach - 0.01, 0), about(Vec3::UnitZ(), 30));
  const Body ground = make(Shape::plane(Vec3::UnitY(), 0), Vec3::Zero());
  const auto cs = contacts(box, ground);
  ASSERT_EQ(cs.size(), 2u);
  // The lowest corners are (-x, -y, +-z) turned 30 degrees about z: at x = 0.5 (s - c), 0.01 deep.
  for (const Contact& contact : cs) {
    EXPECT_NEAR(contact.separation, -0.01, kTol);
    expect_near(contact.normal, Vec3::UnitY(), kTol, "normal");
    EXPECT_NEAR(contact.point.x(), 0.5 * (s - c), kTol);
    EXPECT_NEAR(contact.point.y(), -0.005, kTol);  // midway between corner and plane
    EXPECT_NEAR(std::abs(contact.point.z()), 0.5, kTol);
  }
  EXPECT_NEAR(cs[0].point.z(), -cs[1].point.z(), kTol);
}

TEST(BoxPlane, BoxOnItsCornerTouchesWithThatCornerOnly) {
  // Tilted so that corner 0 (-x, -y, -z) is the lowest, alone.
  const Quat q = about(Vec3(1, 0, -1), 40);
  Body box = unit_box(Vec3::Zero(), q);
  Real lowest = INFINITY;
  int lowest_corner = -1;
  for (int i = 0; i < 8; ++i) {
    const Real y = (q * box_corner(box.shape.half_extents, i)).y();
    if (y < lowest) lowest = y, lowest_corner = i;
  }
  box.position = Vec3(0, -lowest - 0.003, 0);
  const Body ground = make(Shape::plane(Vec3::UnitY(), 0), Vec3::Zero());
  const auto cs = contacts(box, ground);
  ASSERT_EQ(cs.size(), 1u);
  EXPECT_EQ(cs[0].feature, feature::corner(lowest_corner));
  EXPECT_NEAR(cs[0].separation, -0.003, kTol);
  const Vec3 corner = box.position + q * box_corner(box.shape.half_extents, lowest_corner);
  expect_near(cs[0].point, corner + Vec3(0, 0.0015, 0), kTol, "point");
}

// --- sphere against box ------------------------------------------------------------------------

class SphereBox : public ::testing::Test {
 protected:
  const Quat q = about(Vec3(0.2, 1, -0.3), 30);
  const Body box = make(Shape::box(Vec3(0.5, 0.3, 0.4)), Vec3(1, 2, 3), q, true);
  Vec3 world(const Vec3& local) const { return box.position + q * local; }
  Body sphere(const Vec3& local_centre, Real radius = 0.25) const { return make(Shape::sphere(radius), world(local_centre)); }
};

TEST_F(SphereBox, AgainstAFace) {
  const auto cs = contacts(sphere(Vec3(0.1, 0.3 + 0.24, -0.2)), box);
  ASSERT_EQ(cs.size(), 1u);
  expect_near(cs[0].normal, q * Vec3::UnitY(), kTol, "normal");
  EXPECT_NEAR(cs[0].separation, -0.01, kTol);
  expect_near(cs[0].point, world(Vec3(0.1, 0.3 - 0.005, -0.2)), kTol, "point");
}

TEST_F(SphereBox, AgainstAnEdge) {
  const Vec3 out = Vec3(1, 1, 0).normalized();
  const auto cs = contacts(sphere(Vec3(0.5, 0.3, 0.1) + out * 0.2), box);
  ASSERT_EQ(cs.size(), 1u);
  expect_near(cs[0].normal, q * out, kTol, "normal");
  EXPECT_NEAR(cs[0].separation, -0.05, kTol);
  expect_near(cs[0].point, world(Vec3(0.5, 0.3, 0.1) - out * 0.025), kTol, "point");
}

TEST_F(SphereBox, AgainstACorner) {
  const Vec3 out = Vec3(-1, 1, 1).normalized();
  const Vec3 corner(-0.5, 0.3, 0.4);
  const auto cs = contacts(sphere(corner + out * 0.26), box);
  ASSERT_EQ(cs.size(), 1u);
  expect_near(cs[0].normal, q * out, kTol, "normal");
  EXPECT_NEAR(cs[0].separation, 0.01, kTol);  // speculative
  expect_near(cs[0].point, world(corner + out * 0.005), kTol, "point");
  EXPECT_TRUE(contacts(sphere(corner + out * 0.28), box).empty());
}

TEST_F(SphereBox, CentreInsideLeavesThroughTheNearestFace) {
  const auto cs = contacts(sphere(Vec3(0.1, -0.2, 0.05)), box);  // 0.1 from the -y face
  ASSERT_EQ(cs.size(), 1u);
  expect_near(cs[0].normal, q * -Vec3::UnitY(), kTol, "normal");
  EXPECT_NEAR(cs[0].separation, -(0.1 + 0.25), kTol);
  // Midway between the face point (y = -0.3) and the sphere's far side (y = -0.2 + 0.25).
  expect_near(cs[0].point, world(Vec3(0.1, (-0.3 + 0.05) / 2, 0.05)), kTol, "point");
}

TEST_F(SphereBox, OrderDoesNotMatter) {
  std::vector<Contact> out;
  collide(box, 7, sphere(Vec3(0.1, 0.5, 0)), 3, kMargin, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].body_a, 3);  // the sphere is A
  EXPECT_EQ(out[0].body_b, 7);
}

}  // namespace
}  // namespace impulse::physics
