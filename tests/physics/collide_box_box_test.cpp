// Box against box (physics/collide_box_box.cpp): contact points, normals, depths, and feature ids
// that stay put while the boxes barely move.
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

// --- box against box ---------------------------------------------------------------------------

// A unit box lying on another, overhanging it by 0.2 m and tilted `milliradians` about x (at 2
// mrad its lowest points are 0.2 mm into the lower box). Without a cache the reference face
// passes from the lower box to the upper between 2 and 3 mrad.
Body tilted_on_unit_box(Real milliradians) {
  const Real angle = milliradians / 1000;
  return unit_box(Vec3(0, 0.5 + 0.5 * (std::cos(angle) + std::sin(angle)) - 0.0006, 0.2), about(Vec3::UnitX(), angle * 180 / std::numbers::pi));
}

int reference_box(const std::vector<Contact>& cs) { return int((cs.at(0).feature >> 12) & 1); }

TEST(BoxBox, Resting30DegreesTurnedOnALargerBoxGivesItsFourBottomCorners) {
  const Body ground = make(Shape::box(Vec3(2, 0.5, 2)), Vec3::Zero(), Quat::Identity(), true);
  const Quat q = about(Vec3::UnitY(), 30);
  const Body top = unit_box(Vec3(0.3, 1 - 0.01, 0.2), q);
  for (bool top_first : {true, false}) {
    const auto cs = top_first ? contacts(top, ground) : contacts(ground, top);
    ASSERT_EQ(cs.size(), 4u) << "top first " << top_first;
    const Vec3 up = top_first ? Vec3::UnitY() : Vec3(-Vec3::UnitY());  // A is pushed away from B
    std::vector<Vec3> corners;
    for (int i : {0, 1, 4, 5}) corners.push_back(top.position + q * box_corner(top.shape.half_extents, i));
    for (const Contact& c : cs) {
      expect_near(c.normal, up, kTol, "normal");
      EXPECT_NEAR(c.separation, -0.01, kTol);
      EXPECT_NEAR(c.point.y(), 0.495, kTol);
      // Each point sits on one of the top box's bottom corners.
      const auto nearest = std::min_element(corners.begin(), corners.end(), [&](const Vec3& p, const Vec3& r) {
        return (p - c.point).norm() < (r - c.point).norm();
      });
      EXPECT_LT((*nearest + Vec3(0, 0.005, 0) - c.point).norm(), 1e-9);
    }
  }
}

TEST(BoxBox, OffsetAndTurnedFaceContactStaysInsideTheOverlap) {
  const Body lower = make(Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3::Zero(), Quat::Identity(), true);
  const Body upper = unit_box(Vec3(0.6, 1 - 0.01, 0.3), about(Vec3::UnitY(), 30));
  const auto cs = contacts(upper, lower);
  ASSERT_EQ(cs.size(), 4u);
  for (const Contact& c : cs) {
    expect_near(c.normal, Vec3::UnitY(), kTol, "normal");
    EXPECT_NEAR(c.separation, -0.01, kTol);
    EXPECT_NEAR(c.point.y(), 0.495, kTol);
    EXPECT_TRUE(in_footprint(lower, c.point, 1e-6)) << c.point.transpose();
    EXPECT_TRUE(in_footprint(upper, c.point, 1e-6)) << c.point.transpose();
  }
  // The four kept points span most of the overlap polygon: at least 3/4 of its area.
  // (Overlap computed by clipping a fine grid of samples.)
  int inside = 0, samples = 0;
  for (Real x = 0; x <= 0.5; x += 0.005)
    for (Real z = -0.5; z <= 0.5; z += 0.005) {
      ++samples;
      if (in_footprint(upper, Vec3(x, 0, z), 0)) ++inside;
    }
  const Real overlap_area = 0.5 * 1.0 * inside / samples;
  Real quad_area = 0;  // shoelace over the points in their (polygon) order
  for (size_t k = 0; k < cs.size(); ++k) {
    const Vec3& p = cs[k].point;
    const Vec3& r = cs[(k + 1) % cs.size()].point;
    quad_area += (p.z() * r.x() - p.x() * r.z()) / 2;
  }
  EXPECT_GT(std::abs(quad_area), 0.75 * overlap_area);
}

TEST(BoxBox, OctagonOverlapIsReducedToFourSpreadPoints) {
  // Two unit boxes, one turned 45 degrees: the overlap is a regular octagon of 8 corners.
  const Body lower = make(Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3::Zero(), Quat::Identity(), true);
  const Body upper = unit_box(Vec3(0, 1 - 0.01, 0), about(Vec3::UnitY(), 45));
  const auto cs = contacts(upper, lower);
  ASSERT_EQ(cs.size(), 4u);
  Real area = 0;
  for (size_t k = 0; k < cs.size(); ++k) {
    EXPECT_NEAR(cs[k].separation, -0.01, kTol);
    const Vec3& p = cs[k].point;
    const Vec3& r = cs[(k + 1) % cs.size()].point;
    area += (p.z() * r.x() - p.x() * r.z()) / 2;
  }
  const Real octagon = 2 * (std::sqrt(Real(2)) - 1);
  EXPECT_GT(std::abs(area), 0.7 * octagon);  // the best four corners of an octagon hold 1/sqrt(2) of it
}

TEST(BoxBox, TiltedBoxRestsOnItsLowestEdge) {
  const Body ground = make(Shape::box(Vec3(2, 0.5, 2)), Vec3::Zero(), Quat::Identity(), true);
  const Real c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Body box = unit_box(Vec3(0, 0.5 + 0.5 * (c + s) - 0.01, 0), about(Vec3::UnitZ(), 30));
  const auto cs = contacts(box, ground);
  ASSERT_EQ(cs.size(), 2u);
  for (const Contact& contact : cs) {
    expect_near(contact.normal, Vec3::UnitY(), kTol, "normal");
    EXPECT_NEAR(contact.separation, -0.01, kTol);
    EXPECT_NEAR(contact.point.x(), 0.5 * (s - c), kTol);
    EXPECT_NEAR(contact.point.y(), 0.495, kTol);
    EXPECT_NEAR(std::abs(contact.point.z()), 0.5, kTol);
    EXPECT_EQ(contact.feature >> 14, 1u);  // a face contact, not an edge pair
  }
}

TEST(BoxBox, UnitBoxOnTheBenchmarkGroundBox) {
  const Body ground = make(Shape::box(Vec3(100, 0.5, 100)), Vec3(0, -0.5, 0), Quat::Identity(), true);
  const Body box = unit_box(Vec3(3.7, 0.5, -12.1));
  const auto cs = contacts(ground, box);
  ASSERT_EQ(cs.size(), 4u);
  for (const Contact& c : cs) {
    expect_near(c.normal, -Vec3::UnitY(), kTol, "normal");  // A (the ground) is pushed down
    EXPECT_NEAR(c.separation, 0, 1e-12);
    EXPECT_NEAR(std::abs(c.point.x() - 3.7), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(c.point.z() + 12.1), 0.5, 1e-12);
  }
}

TEST(BoxBox, CrossingEdgesGiveOnePointBetweenTheirClosestPoints) {
  // A turned 45 degrees about x: its lowest edge runs along x. B turned 45 degrees about z: its
  // highest edge runs along z. They cross at right angles, overlapping by 0.02.
  const Real r = std::sqrt(Real(0.5));  // half diagonal of a unit square
  const Body b = make(Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3::Zero(), about(Vec3::UnitZ(), 45), true);
  const Body a = unit_box(Vec3(0.05, 2 * r - 0.02, -0.1), about(Vec3::UnitX(), 45));
  const auto cs = contacts(a, b);
  ASSERT_EQ(cs.size(), 1u);
  const Contact& c = cs[0];
  // Normal along x cross z (the edges' cross product), pointing the way A leaves B: up.
  const Vec3 cross = Vec3::UnitX().cross(Vec3::UnitZ());
  EXPECT_NEAR(std::abs(c.normal.dot(cross)), 1, kTol);
  expect_near(c.normal, Vec3::UnitY(), kTol, "normal");
  EXPECT_NEAR(c.separation, -0.02, kTol);
  // Closest points: on B's edge (0, r, z) and A's edge (x, 2r - 0.02 - r, -0.1); crossing at x = 0, z = -0.1.
  expect_near(c.point, Vec3(0, r - 0.01, -0.1), kTol, "point");
  EXPECT_EQ(c.feature >> 14, 2u);
}

TEST(BoxBox, SeparatedBeyondTheMarginGiveNothing) {
  const Body lower = unit_box(Vec3::Zero());
  EXPECT_TRUE(contacts(unit_box(Vec3(0.2, 1.03, 0)), lower).empty());               // face axis
  EXPECT_EQ(contacts(unit_box(Vec3(0.2, 1.01, 0)), lower).size(), 4u);               // speculative
  const Real r = std::sqrt(Real(0.5));
  const Body turned = make(Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3::Zero(), about(Vec3::UnitZ(), 45));
  EXPECT_TRUE(contacts(unit_box(Vec3(0, 2 * r + 0.03, 0), about(Vec3::UnitX(), 45)), turned).empty());  // edge axis
  EXPECT_EQ(contacts(unit_box(Vec3(0, 2 * r + 0.01, 0), about(Vec3::UnitX(), 45)), turned).size(), 1u);
  const Body ball = make(Shape::sphere(0.5), Vec3(0, 1.03, 0));
  EXPECT_TRUE(contacts(ball, lower).empty());
  EXPECT_TRUE(contacts(lower, make(Shape::plane(Vec3::UnitY(), -0.53), Vec3::Zero())).empty());
}

TEST(BoxBox, ARockingBoxKeepsItsReferenceFaceWhileItsPointsStayWithinASlop) {
  const Body lower = unit_box(Vec3::Zero());
  auto collide_cached = [&](Real milliradians, SatCache* cache) {
    std::vector<Contact> out;
    collide(lower, 0, tilted_on_unit_box(milliradians), 1, kMargin, out, cache);
    return out;
  };
  ASSERT_EQ(reference_box(collide_cached(2, nullptr)), 0) << "the lower box's face";
  ASSERT_EQ(reference_box(collide_cached(3, nullptr)), 1) << "the upper box's face";

  SatCache cache;
  EXPECT_EQ(reference_box(collide_cached(2, &cache)), 0);
  EXPECT_EQ(cache.reference, 0);
  const auto rocked = collide_cached(3, &cache);
  EXPECT_EQ(reference_box(rocked), 0) << "kept: its deepest point moved 0.2 mm";
  EXPECT_EQ(rocked.size(), 4u);
  // At 40 mrad the deepest point on the cached face is 6.8 mm from where it was, beyond the slop:
  // the axes are tested again.
  EXPECT_EQ(reference_box(collide_cached(40, &cache)), 1);
  EXPECT_EQ(cache.reference, 1);
}



// --- feature ids -------------------------------------------------------------------------------

TEST(Features, UnchangedAfterATinyMotion) {
  const Body ground = make(Shape::box(Vec3(3, 0.5, 3)), Vec3::Zero(), Quat::Identity(), true);
  const Body plane = make(Shape::plane(Vec3::UnitY(), 0.5), Vec3::Zero());
  const Body same_size = make(Shape::box(Vec3(0.5, 0.5, 0.5)), Vec3(0, 0, 0), Quat::Identity(), true);
  const Quat q = about(Vec3::UnitY(), 20);
  const Body before = unit_box(Vec3(0.2, 1 - 0.001, 0.1), q);
  Body after = before;
  after.position += Vec3(1e-4, -2e-4, 3e-5);
  after.orientation = (about(Vec3(1, 0.3, 0.5), 0.01) * before.orientation).normalized();

  const Body flush = unit_box(Vec3(0, 1 - 0.001, 0));  // flush edges with `same_size`
  Body flush_after = flush;
  flush_after.position += Vec3(2e-4, 1e-4, -3e-4);
  flush_after.orientation = about(Vec3(0.3, 1, 0.2), 0.01);

  struct Case { const char* name; const Body &a, &b, &a2, &b2; size_t count; };
  const Case cases[] = {
      {"box on ground box", before, ground, after, ground, 4},
      {"ground box under box", ground, before, ground, after, 4},
      {"box on plane", before, plane, after, plane, 4},
      {"flush stack", flush, same_size, flush_after, same_size, 4},
      {"flush stack, lower first", same_size, flush, same_size, flush_after, 4},
  };
  for (const Case& c : cases) {
    const auto first = contacts(c.a, c.b), second = contacts(c.a2, c.b2);
    EXPECT_EQ(first.size(), c.count) << c.name;
    EXPECT_EQ(features(first), features(second)) << c.name;
    auto f = features(first);
    std::sort(f.begin(), f.end());
    EXPECT_EQ(std::unique(f.begin(), f.end()), f.end()) << c.name << ": ids repeat";
  }
}

}  // namespace
}  // namespace impulse::physics
