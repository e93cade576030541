// Convex hulls: their polyhedra (qhull), their mass properties against closed forms, and their
// contacts with every shape (collide_hull.cpp, collide_convex.cpp) by geometry worked by hand.
#include "physics/body.h"
#include "physics/collide.h"
#include "physics/hull.h"
#include "tests/physics/placed_bodies.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace impulse::physics {
namespace {

using namespace placing;

std::vector<Vec3> cube_points(Real half) {
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) points.push_back(box_corner(Vec3::Constant(half), i));
  return points;
}

Shape hull_of(const std::vector<Vec3>& points) { return Shape::convex(place_hull(points, false).hull); }

const Body kGround = placed(Shape::plane(Vec3::UnitY(), 0), Vec3::Zero());

TEST(Hull, ACubesPointsMakeSixSquareFacesAndPointsInsideOrOnAFaceAreNoCorners) {
  std::vector<Vec3> points = cube_points(0.5);
  points.push_back(Vec3(0.1, -0.2, 0.3));  // inside
  points.push_back(Vec3(0.5, 0.1, 0.2));   // on the +x face
  points.push_back(Vec3(0, 0.5, 0.5));     // on an edge
  const Hull hull = convex_hull(points);
  EXPECT_EQ(hull.corners.size(), 8u);
  ASSERT_EQ(hull.faces.size(), 6u);
  for (const HullFace& face : hull.faces) {
    EXPECT_EQ(face.count, 4);
    EXPECT_NEAR(face.offset, 0.5, 1e-12);
    // Counter-clockwise seen from outside.
    const Vec3 a = hull.corners[hull.corner_of(face, 0)], b = hull.corners[hull.corner_of(face, 1)], c = hull.corners[hull.corner_of(face, 2)];
    EXPECT_GT((b - a).cross(c - b).dot(face.normal), 0);
  }
  EXPECT_NEAR(hull.volume, 1, 1e-12);
  EXPECT_NEAR(hull.area, 6, 1e-12);
}

TEST(Hull, ACubesMassPropertiesAreABoxsSolidAndHollow) {
  const Shape cube = hull_of(cube_points(0.3)), box = Shape::box(Vec3::Constant(0.3));
  EXPECT_NEAR(shape_volume(cube), shape_volume(box), 1e-12);
  EXPECT_LT((shape_unit_inertia(cube) - shape_unit_inertia(box)).norm(), 1e-12);
  EXPECT_LT((shape_unit_shell_inertia(cube) - shape_unit_shell_inertia(box)).norm(), 1e-12);
}

TEST(Hull, ARegularTetrahedronsInertiaIsATwentiethOfItsEdgeSquaredAboutEveryAxis) {
  // I = m a^2 / 20 about any axis through the centroid; V = a^3 / (6 sqrt 2).
  const Real a = 0.7;
  const PlacedHull placed = place_hull(tetrahedron_points(a), false);
  EXPECT_NEAR(placed.hull->volume, a * a * a / (6 * std::sqrt(2.0)), 1e-12);
  EXPECT_LT((placed.hull->unit_inertia - Mat3::Identity() * (a * a / 20)).norm(), 1e-9 * a * a);
  EXPECT_LT(placed.centre.norm(), 1e-12);  // the points were about the centroid already
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : placed.hull->corners) mean += p / 4;
  EXPECT_LT(mean.norm(), 1e-12);
}

TEST(Hull, AWedgesCentreAndPrincipalMomentsAreTheRightTrianglesClosedForms) {
  // The right triangle of legs a (x) and b (y) drawn along z by c. About its centroid (a/3, b/3
  // from the right angle), per unit mass: second moments a^2/18, b^2/18, c^2/12, product -ab/36.
  const Real a = 0.9, b = 0.4, c = 0.5;
  const Real ixx = b * b / 18 + c * c / 12, iyy = a * a / 18 + c * c / 12, izz = (a * a + b * b) / 18, ixy = a * b / 36;
  const Hull given = convex_hull(wedge_points(Vec3(a, b, c)));
  EXPECT_NEAR(given.volume, a * b * c / 2, 1e-12);
  // convex_hull's tensor is about the points' origin (the box's centre): move it to the centroid.
  const Vec3 centroid(-a / 6, -b / 6, 0);
  const Mat3 about_origin = given.unit_inertia;
  const Mat3 about_centroid = about_origin - (Mat3::Identity() * centroid.squaredNorm() - centroid * centroid.transpose());
  Mat3 expected;
  expected << ixx, ixy, 0, ixy, iyy, 0, 0, 0, izz;
  EXPECT_LT((about_centroid - expected).norm(), 1e-9 * expected.norm());

  const PlacedHull placed = place_hull(wedge_points(Vec3(a, b, c)), false);
  EXPECT_LT((placed.centre - centroid).norm(), 1e-12);
  const Real mean = (ixx + iyy) / 2, half_gap = std::hypot((ixx - iyy) / 2, ixy);
  const Mat3& principal = placed.hull->unit_inertia;
  EXPECT_LT(std::abs(principal(0, 1)) + std::abs(principal(0, 2)) + std::abs(principal(1, 2)), 1e-12);
  // Each principal axis stays nearest its given axis: the larger moment (about the more nearly x) first.
  EXPECT_NEAR(principal(0, 0), mean - half_gap, 1e-9 * mean);
  EXPECT_NEAR(principal(1, 1), mean + half_gap, 1e-9 * mean);
  EXPECT_NEAR(principal(2, 2), izz, 1e-9 * izz);
  // The frame takes the hull back onto the given points.
  for (const Vec3& p : placed.hull->corners) {
    const Vec3 back = placed.centre + rotate(placed.frame, p);
    Real nearest = INFINITY;
    for (const Vec3& q : wedge_points(Vec3(a, b, c))) nearest = std::min(nearest, (q - back).norm());
    EXPECT_LT(nearest, 1e-12);
  }
}

TEST(Hull, APrismsVolumeIsItsPolygonsAreaTimesItsHeight) {
  const Real r = 0.3, h = 0.8;
  for (int sides = 3; sides <= 12; ++sides) {
    const Hull hull = convex_hull(prism_points(sides, r, h));
    EXPECT_NEAR(hull.volume, sides * r * r * std::sin(2 * std::numbers::pi / sides) / 2 * h, 1e-12) << sides;
    EXPECT_EQ(hull.faces.size(), size_t(sides + 2)) << sides;
  }
}

TEST(Hull, AFacesQuadLiesOnItsSidesAndLeavesNoSideOfARegularPolygonNearItsCentre) {
  const Real r = 0.3;
  for (int sides = 5; sides <= 16; ++sides) {
    const Hull hull = convex_hull(prism_points(sides, r, 0.5));
    const Real apothem = r * std::cos(std::numbers::pi / sides);
    int ends = 0;
    for (const HullFace& face : hull.faces) {
      if (face.count <= 4) continue;
      ++ends;
      const Vec3 centre = face.normal * face.offset;  // a prism's end: its centre is on the axis
      for (int q = 0; q < 4; ++q) {
        const Vec3& p = face.quad[q];
        const Vec3& next = face.quad[(q + 1) % 4];
        EXPECT_NEAR(face.normal.dot(p), face.offset, 1e-12);
        // On a side of the polygon: as far from the axis as the side's line there.
        Vec3 in_plane = p - centre;
        const Real angle = std::atan2(in_plane.z(), in_plane.x());
        const Real side_angle = std::floor(angle / (2 * std::numbers::pi / sides)) * (2 * std::numbers::pi / sides) + std::numbers::pi / sides;
        EXPECT_NEAR(in_plane.x() * std::cos(side_angle) + in_plane.z() * std::sin(side_angle), apothem, 1e-9) << sides;
        // Counter-clockwise seen from outside, and the centre more than half the apothem inside each side.
        const Vec3 inward = face.normal.cross(next - p).normalized();
        EXPECT_GT(inward.dot(centre - p), apothem / 2) << sides;
      }
    }
    EXPECT_EQ(ends, 2) << sides;
  }
}

TEST(Hull, PointsThatSpanNoSolidAreRefusedWithTheReason) {
  auto reason = [](const std::vector<Vec3>& points) {
    try {
      convex_hull(points);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(reason({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).find("at least 4 points"), std::string::npos);
  EXPECT_NE(reason({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}}).find("one plane"), std::string::npos);
  EXPECT_NE(reason({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).find("one line"), std::string::npos);
  EXPECT_NE(reason({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}).find("same point"), std::string::npos);
}

TEST(CollideHull, ACubeHullOnTheGroundTouchesAtItsFourLowerCorners) {
  const Body cube = placed(hull_of(cube_points(0.25)), Vec3(0, 0.249, 0), about(Vec3::UnitY(), 30));
  const auto out = contacts(cube, kGround);
  ASSERT_EQ(out.size(), 4u);
  for (const Contact& c : out) {
    EXPECT_NEAR(c.separation, -0.001, 1e-12);
    EXPECT_LT((c.normal - Vec3::UnitY()).norm(), 1e-12);
  }
}

TEST(CollideHull, APentagonalPrismStandingOnTheGroundTouchesAtItsEndsQuad) {
  const PlacedHull pentagonal = place_hull(prism_points(5, 0.3, 0.4), false);
  const Hull& hull = *pentagonal.hull;
  const Body prism = placed(Shape::convex(pentagonal.hull), Vec3(0, 0.2 - 0.001, 0));
  const auto out = contacts(prism, kGround);
  ASSERT_EQ(out.size(), 4u);
  Vec3 mean = Vec3::Zero();
  for (const Contact& c : out) {
    EXPECT_NEAR(c.separation, -0.001, 1e-12);
    mean += c.point / 4;
    bool on_quad = false;
    for (const HullFace& face : hull.faces)
      if (face.count > 4 && face.normal.y() < 0)
        for (const Vec3& q : face.quad) on_quad = on_quad || (q + prism.position - c.point).norm() < 0.0006;
    EXPECT_TRUE(on_quad);
  }
  // Tipped 10 degrees about x: its lowest corner alone, deeper than the quad.
  const Body tipped = placed(hull_of(prism_points(5, 0.3, 0.4)), Vec3(0, 0.2, 0), about(Vec3::UnitX(), 10));
  const Real lowest = reach_along(tipped.shape, tipped.orientation, -Vec3::UnitY());
  const Body tipped_in = placed(tipped.shape, Vec3(0, lowest - 0.001, 0), tipped.orientation);
  const auto corner = contacts(tipped_in, kGround);
  ASSERT_GE(corner.size(), 1u);
  Real deepest = 0;
  for (const Contact& c : corner) deepest = std::min(deepest, c.separation);
  EXPECT_NEAR(deepest, -0.001, 1e-12);
}

TEST(CollideHull, ATetrahedronOnItsApexTouchesTheGroundThere) {
  // Upside down: the apex (3/4 of the height above the centre) down, 2 mm into the ground.
  const Real a = 0.6, height = a * std::sqrt(2.0 / 3);
  const Body tet = placed(hull_of(tetrahedron_points(a)), Vec3(0, 0.75 * height - 0.002, 0), about(Vec3::UnitX(), 180));
  const auto out = contacts(tet, kGround);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].separation, -0.002, 1e-12);
  EXPECT_NEAR(out[0].point.x(), 0, 1e-12);
}

TEST(CollideHull, ASphereMeetsAHullsFaceEdgeAndCornerAlongTheLineToTheNearestPoint) {
  const Body cube = placed(hull_of(cube_points(0.5)), Vec3::Zero());
  const Real r = 0.2;
  // Over the +y face, 1 mm in.
  auto face = contacts(placed(Shape::sphere(r), Vec3(0.1, 0.5 + r - 0.001, 0.2)), cube);
  ASSERT_EQ(face.size(), 1u);
  EXPECT_NEAR(face[0].separation, -0.001, 1e-12);
  EXPECT_LT((face[0].normal - Vec3::UnitY()).norm(), 1e-12);
  // Beyond the edge along z at x = y = 0.5: along the diagonal, 3 mm apart.
  const Vec3 diagonal = Vec3(1, 1, 0).normalized();
  auto edge = contacts(placed(Shape::sphere(r), Vec3(0.5, 0.5, 0.1) + diagonal * (r + 0.003)), cube);
  ASSERT_EQ(edge.size(), 1u);
  EXPECT_NEAR(edge[0].separation, 0.003, 1e-12);
  EXPECT_LT((edge[0].normal - diagonal).norm(), 1e-12);
  // Beyond the corner (0.5, 0.5, 0.5), 2 mm in.
  const Vec3 out = Vec3(1, 1, 1).normalized();
  auto corner = contacts(placed(Shape::sphere(r), Vec3::Constant(0.5) + out * (r - 0.002)), cube);
  ASSERT_EQ(corner.size(), 1u);
  EXPECT_NEAR(corner[0].separation, -0.002, 1e-12);
  EXPECT_LT((corner[0].normal - out).norm(), 1e-12);
  // The centre inside, nearest the -x face: out through it.
  auto inside = contacts(placed(Shape::sphere(r), Vec3(-0.45, 0.1, 0)), cube);
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_NEAR(inside[0].separation, -0.05 - r, 1e-12);
  EXPECT_LT((inside[0].normal + Vec3::UnitX()).norm(), 1e-12);
  // Far: nothing.
  EXPECT_TRUE(contacts(placed(Shape::sphere(r), Vec3(0, 0.5 + r + 0.02, 0)), cube).empty());
}

TEST(CollideHull, AHullRestingOnAHullOrABoxTouchesAtTheCornersOfTheOverlap) {
  // A unit cube hull under a small cube hull turned 45 degrees about y, 1 mm in: its four lower
  // corners lie inside the big one's top face.
  const Body big = placed(hull_of(cube_points(0.5)), Vec3::Zero());
  const Body small = placed(hull_of(cube_points(0.2)), Vec3(0.1, 0.5 + 0.2 - 0.001, 0), about(Vec3::UnitY(), 45));
  for (const Body& under : {big, placed(Shape::box(Vec3::Constant(0.5)), Vec3::Zero())}) {
    const auto out = contacts(small, under);
    ASSERT_EQ(out.size(), 4u);
    for (const Contact& c : out) {
      EXPECT_NEAR(c.separation, -0.001, 1e-9);
      EXPECT_LT((c.normal - Vec3::UnitY()).norm(), 1e-9);
      EXPECT_NEAR(c.point.y(), 0.5 - 0.0005, 1e-9);
    }
  }
  // A square prism standing across the big cube's top's edge (x = 0.5): the overlap's corners, two
  // of its own and two where its sides cross the edge's side plane.
  const Body prism = placed(hull_of(prism_points(4, 0.2, 0.6)), Vec3(0.5, 0.5 + 0.3 - 0.001, 0), about(Vec3::UnitY(), 45));
  const auto across = contacts(prism, big);
  ASSERT_EQ(across.size(), 4u);
  int on_edge = 0;
  for (const Contact& c : across) {
    EXPECT_NEAR(c.separation, -0.001, 1e-9);
    EXPECT_LE(c.point.x(), 0.5 + 1e-9);
    on_edge += std::abs(c.point.x() - 0.5) < 1e-9;
  }
  EXPECT_EQ(on_edge, 2);
}

TEST(CollideHull, ACylinderAndACapsuleLieOnAHullsFaceAlongALine) {
  const Body cube = placed(hull_of(cube_points(0.5)), Vec3::Zero());
  const Body cylinder = placed(Shape::cylinder(0.1, 0.2), Vec3(0, 0.5 + 0.1 - 0.001, 0), about(Vec3::UnitX(), 90));
  const Body capsule = placed(Shape::capsule(0.1, 0.2), Vec3(0, 0.5 + 0.1 - 0.001, 0), about(Vec3::UnitZ(), 90));
  for (const Body& body : {cylinder, capsule}) {
    const auto out = contacts(body, cube);
    ASSERT_EQ(out.size(), 2u);
    for (const Contact& c : out) {
      EXPECT_NEAR(c.separation, -0.001, 1e-9);
      EXPECT_LT((c.normal - Vec3::UnitY()).norm(), 1e-9);
    }
    EXPECT_NEAR((out[0].point - out[1].point).norm(), 0.4, 1e-9);
  }
}

}  // namespace
}  // namespace impulse::physics
