// Capsules and cylinders: their contacts with every shape (collide_capsule.cpp, collide_convex.cpp)
// by geometry worked by hand, and their mass properties against a count of the volume.
#include "physics/body.h"
#include "physics/collide.h"
#include "tests/physics/placed_bodies.h"
#include "physics/manifold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impulse::physics {
namespace {

using namespace placing;

const Body kGround = placed(Shape::plane(Vec3::UnitY(), 0), Vec3::Zero());

TEST(CollideRound, ACylinderOnItsSideTouchesTheGroundAtBothEndsOfALine) {
  // Axis along z, 1 mm into the ground.
  const Body c = placed(Shape::cylinder(0.2, 0.5), Vec3(1, 0.199, 0), about(Vec3::UnitX(), 90));
  const auto out = contacts(c, kGround);
  ASSERT_EQ(out.size(), 2u);
  for (const Contact& k : out) {
    EXPECT_NEAR(k.separation, -0.001, 1e-12);
    EXPECT_NEAR(k.normal.y(), 1, 1e-15);
    EXPECT_NEAR(k.point.x(), 1, 1e-12);
    EXPECT_NEAR(std::abs(k.point.z()), 0.5, 1e-12);
    EXPECT_TRUE(feature::round_of(k.feature, 0));
  }
}

TEST(CollideRound, ACylinderStandingOnAFaceRestsOnFourRimPoints) {
  const Body c = placed(Shape::cylinder(0.2, 0.5), Vec3(0, 0.4995, 0), about(Vec3::UnitY(), 17));
  const auto out = contacts(c, kGround);
  ASSERT_EQ(out.size(), 4u);
  Vec3 centre = Vec3::Zero();
  for (const Contact& k : out) {
    EXPECT_NEAR(k.separation, -0.0005, 1e-12);
    EXPECT_NEAR(std::hypot(k.point.x(), k.point.z()), 0.2, 1e-12);
    EXPECT_FALSE(feature::round_of(k.feature, 0));
    centre += k.point / 4;
  }
  EXPECT_NEAR(centre.x(), 0, 1e-12);  // spread round the rim
  EXPECT_NEAR(centre.z(), 0, 1e-12);
}

TEST(CollideRound, ATiltedCylinderTouchesAtItsRimsLowestPoint) {
  const double tilt = 30 * std::numbers::pi / 180, r = 0.2, h = 0.5;
  const double lowest = h * std::cos(tilt) + r * std::sin(tilt);  // centre height touching
  const Body c = placed(Shape::cylinder(r, h), Vec3(0, lowest - 0.002, 0), about(Vec3::UnitZ(), 30));
  const auto out = contacts(c, kGround);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].separation, -0.002, 1e-12);
}

TEST(CollideRound, ACapsuleLyingOnTheGroundTouchesUnderBothBalls) {
  const Body c = placed(Shape::capsule(0.1, 0.3), Vec3(0, 0.099, 0), about(Vec3::UnitZ(), 90));
  const auto out = contacts(c, kGround);
  ASSERT_EQ(out.size(), 2u);
  for (const Contact& k : out) {
    EXPECT_NEAR(k.separation, -0.001, 1e-12);
    EXPECT_NEAR(std::abs(k.point.x()), 0.3, 1e-12);
  }
}

TEST(CollideRound, ASpherePressesOnACapsuleAlongTheLineFromItsSegment) {
  const Body cap = placed(Shape::capsule(0.1, 0.3), Vec3::Zero());  // axis along y
  const Body ball = placed(Shape::sphere(0.05), Vec3(0.1, 0.2, 0.1));
  const auto out = contacts(ball, cap);
  ASSERT_EQ(out.size(), 1u);
  const double d = std::hypot(0.1, 0.1);
  EXPECT_NEAR(out[0].separation, d - 0.15, 1e-12);
  EXPECT_NEAR(out[0].normal.x(), 0.1 / d, 1e-12);
  EXPECT_NEAR(out[0].normal.y(), 0, 1e-12);
  // Past the segment's end: from the end's centre.
  const Body above = placed(Shape::sphere(0.05), Vec3(0, 0.44, 0));
  const auto top = contacts(above, cap);
  ASSERT_EQ(top.size(), 1u);
  EXPECT_NEAR(top[0].separation, 0.44 - 0.3 - 0.15, 1e-12);
  EXPECT_NEAR(top[0].normal.y(), 1, 1e-12);
}

TEST(CollideRound, ASpherePressesOnACylindersSideFaceAndRim) {
  const Body cyl = placed(Shape::cylinder(0.2, 0.3), Vec3::Zero(), about(Vec3::UnitX(), 90));  // axis along z
  // Beside the side: along the radius.
  auto side = contacts(placed(Shape::sphere(0.1), Vec3(0, 0.29, 0.1)), cyl);
  ASSERT_EQ(side.size(), 1u);
  EXPECT_NEAR(side[0].separation, -0.01, 1e-12);
  EXPECT_NEAR(side[0].normal.y(), 1, 1e-12);
  // Before a face: along the axis.
  auto face = contacts(placed(Shape::sphere(0.1), Vec3(0.05, 0.05, 0.395)), cyl);
  ASSERT_EQ(face.size(), 1u);
  EXPECT_NEAR(face[0].separation, -0.005, 1e-12);
  EXPECT_NEAR(face[0].normal.z(), 1, 1e-12);
  // Past the rim: from the rim's nearest point.
  auto rim = contacts(placed(Shape::sphere(0.1), Vec3(0, 0.25, 0.34)), cyl);
  ASSERT_EQ(rim.size(), 1u);
  EXPECT_NEAR(rim[0].separation, std::hypot(0.05, 0.04) - 0.1, 1e-12);
  // The centre inside: out through the nearer face.
  auto inside = contacts(placed(Shape::sphere(0.1), Vec3(0, 0.0, 0.28)), cyl);
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_NEAR(inside[0].normal.z(), 1, 1e-12);
  EXPECT_NEAR(inside[0].separation, -0.02 - 0.1, 1e-12);
}

// A box's face is the reference: the other's points clipped to it, measured along its normal exactly.
TEST(CollideRound, ACylinderOnABoxTouchesAlongTheLineClippedToTheFace) {
  const Body ramp = placed(Shape::box(Vec3(0.3, 0.1, 1)), Vec3::Zero());
  const Body cyl = placed(Shape::cylinder(0.2, 0.5), Vec3(0.1, 0.1 + 0.2 - 0.001, 0.7), about(Vec3::UnitX(), 90));  // axis along z
  const auto out = contacts(cyl, ramp);
  ASSERT_EQ(out.size(), 2u);
  double zs[2];
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(out[i].separation, -0.001, 1e-9);
    EXPECT_NEAR(out[i].normal.y(), 1, 1e-12) << "the face's normal";
    EXPECT_NEAR(out[i].point.x(), 0.1, 1e-9);
    zs[i] = out[i].point.z();
  }
  // The line runs z 0.2 .. 1.2; the box's face ends at z = 1.
  EXPECT_NEAR(std::min(zs[0], zs[1]), 0.2, 1e-9);
  EXPECT_NEAR(std::max(zs[0], zs[1]), 1.0, 1e-9);
}

TEST(CollideRound, ABoxOnACylindersFaceRestsOnItsCornersInsideTheRim) {
  const Body can = placed(Shape::cylinder(0.5, 0.2), Vec3::Zero());
  const Body box = placed(Shape::box(Vec3(0.1, 0.1, 0.1)), Vec3(0.05, 0.2 + 0.1 - 0.002, 0), about(Vec3::UnitY(), 30));
  const auto out = contacts(box, can);
  ASSERT_EQ(out.size(), 4u);
  for (const Contact& k : out) {
    EXPECT_NEAR(k.separation, -0.002, 1e-9);
    EXPECT_NEAR(k.normal.y(), 1, 1e-12);
  }
}

TEST(CollideRound, CylindersStackedFaceOnFace) {
  const Body low = placed(Shape::cylinder(0.3, 0.2), Vec3::Zero());
  const Body high = placed(Shape::cylinder(0.3, 0.2), Vec3(0.01, 0.4 - 0.001, 0), about(Vec3::UnitY(), 10));
  const auto out = contacts(high, low);
  ASSERT_EQ(out.size(), 4u);
  for (const Contact& k : out) {
    EXPECT_NEAR(k.separation, -0.001, 1e-9);
    EXPECT_NEAR(std::abs(k.normal.y()), 1, 1e-12);
  }
}

TEST(CollideRound, CapsulesSideBySideTouchAtTheirOverlapsEnds) {
  const Body a = placed(Shape::capsule(0.1, 0.4), Vec3(0, 0, 0), about(Vec3::UnitZ(), 90));   // along x, -0.4 .. 0.4
  const Body b = placed(Shape::capsule(0.1, 0.4), Vec3(0.3, 0.199, 0), about(Vec3::UnitZ(), 90));  // -0.1 .. 0.7
  const auto out = contacts(b, a);
  ASSERT_EQ(out.size(), 2u);
  double xs[2];
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(out[i].separation, -0.001, 1e-6);
    EXPECT_NEAR(out[i].normal.y(), 1, 1e-4);
    xs[i] = out[i].point.x();
  }
  EXPECT_NEAR(std::min(xs[0], xs[1]), -0.1, 1e-3);
  EXPECT_NEAR(std::max(xs[0], xs[1]), 0.4, 1e-3);
}

TEST(CollideRound, CrossedCapsulesTouchAtOnePoint) {
  const Body a = placed(Shape::capsule(0.1, 0.4), Vec3(0, 0, 0), about(Vec3::UnitZ(), 90));  // along x
  const Body b = placed(Shape::capsule(0.1, 0.4), Vec3(0, 0.195, 0), about(Vec3::UnitX(), 90));  // along z
  const auto out = contacts(b, a);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].separation, -0.005, 1e-5);
  EXPECT_NEAR(out[0].normal.y(), 1, 1e-3);
  EXPECT_NEAR(out[0].point.norm(), 0.0975, 1e-3);
}

TEST(CollideRound, ApartByMoreThanTheMarginThereIsNoContact) {
  const Body ramp = placed(Shape::box(Vec3(0.3, 0.1, 1)), Vec3::Zero());
  const Body cyl = placed(Shape::cylinder(0.2, 0.5), Vec3(0, 0.1 + 0.2 + 0.02, 0), about(Vec3::UnitX(), 90));
  EXPECT_TRUE(contacts(cyl, ramp, 0.01).empty());
  EXPECT_EQ(contacts(cyl, ramp, 0.03).size(), 2u);  // a speculative line, 2 cm apart
  for (const Contact& k : contacts(cyl, ramp, 0.03)) EXPECT_NEAR(k.separation, 0.02, 1e-9);
}

// The mass properties by another road: both are solids of turning about y, so a sum over thin
// discs of radius rho(y) (a disc's own moments rho^2/2 about its axis, rho^2/4 across it, moved by y).
Mat3 sliced_unit_inertia(const Shape& s, int n) {
  const Real reach = s.half_height + (s.type == ShapeType::capsule ? s.radius : 0);
  Real mass = 0, axial = 0, across = 0;
  for (int i = 0; i < n; ++i) {
    const Real y = (i + Real(0.5)) / n * 2 * reach - reach;
    const Real beyond = std::max(std::abs(y) - s.half_height, Real(0));
    const Real rho2 = s.radius * s.radius - beyond * beyond;
    if (rho2 <= 0) continue;
    const Real dm = std::numbers::pi * rho2;
    mass += dm;
    axial += dm * rho2 / 2;
    across += dm * (rho2 / 4 + y * y);
  }
  return Mat3(Vec3(across, axial, across).asDiagonal()) / mass;
}

TEST(CollideRound, CapsulesAndCylindersInertiaIsTheirDiscsSummed) {
  for (const Shape& s : {Shape::cylinder(0.2, 0.5), Shape::cylinder(0.5, 0.05), Shape::capsule(0.1, 0.3), Shape::capsule(0.3, 0.05)}) {
    const Mat3 formula = shape_unit_inertia(s), sliced = sliced_unit_inertia(s, 400000);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(formula(k, k) / sliced(k, k), 1, 1e-9) << int(s.type) << " axis " << k;
  }
  // A capsule without a segment is a ball; a cylinder's closed forms.
  EXPECT_NEAR(shape_unit_inertia(Shape::capsule(0.3, 1e-12))(0, 0), 0.4 * 0.09, 1e-12);
  EXPECT_NEAR(shape_volume(Shape::capsule(0.3, 1e-12)), 4.0 / 3 * std::numbers::pi * 0.027, 1e-12);
  EXPECT_NEAR(shape_unit_inertia(Shape::cylinder(0.2, 0.5))(1, 1), 0.02, 1e-15);
  EXPECT_NEAR(shape_unit_inertia(Shape::cylinder(0.2, 0.5))(0, 0), (3 * 0.04 + 1.0) / 12, 1e-15);
  // Hollow: a tube's m R^2 about its axis; a capsule's shell without a segment is a spherical shell.
  EXPECT_NEAR(shape_unit_shell_inertia(Shape::cylinder(0.2, 0.5))(1, 1), 0.04, 1e-15);
  EXPECT_NEAR(shape_unit_shell_inertia(Shape::capsule(0.3, 1e-12))(2, 2), 2.0 / 3 * 0.09, 1e-12);
}

}  // namespace
}  // namespace impulse::physics
