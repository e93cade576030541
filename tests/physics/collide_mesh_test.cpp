// Static meshes, hand-worked: which seams are convex, the nearest part of a triangle, and the
// contacts of bodies resting on, sliding over and rolling into triangles.
#include "physics/collide.h"
#include "physics/mesh.h"
#include "tests/physics/placed_bodies.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

namespace impulse::physics {
namespace {

using placing::about;
using placing::contacts;
using placing::placed;

// Two triangles side by side along x = 0, the second's far edge raised to `rise` (0: a flat
// square; > 0: a valley; < 0: a ridge), facing up.
Mesh fold(Real rise) {
  const std::vector<Vec3> vertices{{-1, 0, -1}, {-1, 0, 1}, {0, 0, 1}, {0, 0, -1}, {1, rise, -1}, {1, rise, 1}};
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {0, 2, 3}, {3, 2, 5}, {3, 5, 4}};
  return make_mesh(vertices, triangles);
}

// The edge of `t` from corner a to corner b, as its index 0-2.
int edge_of(const MeshTriangle& t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if ((t.corners[k] == a && t.corners[(k + 1) % 3] == b) || (t.corners[k] == b && t.corners[(k + 1) % 3] == a)) return k;
  return -1;
}

bool convex(const Mesh& mesh, int triangle, int a, int b) { return mesh.triangles[triangle].convex_edges >> edge_of(mesh.triangles[triangle], a, b) & 1; }

TEST(Mesh, FlatSeamsAndValleysAreNotConvexRidgesAndRimsAre) {
  const Mesh flat = fold(0), valley = fold(0.5), ridge = fold(-0.5);
  for (const MeshTriangle& t : flat.triangles) EXPECT_NEAR(t.normal.y(), 1, 1e-15);
  EXPECT_FALSE(convex(flat, 0, 0, 2));   // the square's own diagonal
  EXPECT_FALSE(convex(flat, 1, 2, 3));   // the seam at x = 0, flat
  EXPECT_FALSE(convex(valley, 1, 2, 3));
  EXPECT_FALSE(convex(valley, 2, 2, 3));
  EXPECT_TRUE(convex(ridge, 1, 2, 3));
  EXPECT_TRUE(convex(ridge, 2, 2, 3));
  EXPECT_TRUE(convex(flat, 0, 0, 1));    // the rim
  // A seam folded by less than 5 degrees is flat enough: tan 4 deg = 0.070.
  EXPECT_FALSE(convex(fold(-0.069), 1, 2, 3));
  EXPECT_TRUE(convex(fold(-0.1), 1, 2, 3));
}

TEST(Mesh, TheSameCornerWrittenTwiceIsOneAndBadTrianglesAreRefusedInWords) {
  // The second triangle names copies of the first's corners: one seam, not two rims.
  const std::vector<Vec3> vertices{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  const Mesh mesh = make_mesh(vertices, std::vector<std::array<int, 3>>{{0, 1, 2}, {3, 4, 5}});
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_FALSE(convex(mesh, 0, 1, 2));
  const std::vector<Vec3> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  try {
    make_mesh(line, std::vector<std::array<int, 3>>{{0, 1, 2}});
    FAIL() << "a triangle without area was taken";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "triangle 1 has no area: its corners [0, 0, 0], [1, 0, 0] and [2, 0, 0] are on one line");
  }
  EXPECT_THROW(make_mesh(line, std::vector<std::array<int, 3>>{{0, 1, 3}}), std::invalid_argument);
  EXPECT_THROW(make_mesh(line, std::vector<std::array<int, 3>>{}), std::invalid_argument);
}

TEST(Mesh, TheNearestPartOfATriangle) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  Vec3 nearest;
  EXPECT_EQ(nearest_on_triangle({0.5, 0.5, 3}, a, b, c, nearest), 0);
  EXPECT_TRUE(nearest.isApprox(Vec3(0.5, 0.5, 0)));
  EXPECT_EQ(nearest_on_triangle({1, -1, 0}, a, b, c, nearest), 1);  // edge a-b
  EXPECT_TRUE(nearest.isApprox(Vec3(1, 0, 0)));
  EXPECT_EQ(nearest_on_triangle({2, 2, 0}, a, b, c, nearest), 2);   // edge b-c
  EXPECT_TRUE(nearest.isApprox(Vec3(1, 1, 0)));
  EXPECT_EQ(nearest_on_triangle({-1, 1, 0}, a, b, c, nearest), 3);  // edge c-a
  EXPECT_EQ(nearest_on_triangle({-1, -1, 0}, a, b, c, nearest), 4);
  EXPECT_EQ(nearest_on_triangle({3, -1, 0}, a, b, c, nearest), 5);
  EXPECT_EQ(nearest_on_triangle({-1, 3, 0}, a, b, c, nearest), 6);
}

Body floor_of(const Mesh& mesh) {
  Body body = placed(Shape::surface(std::make_shared<const Mesh>(mesh)), Vec3::Zero());
  EXPECT_TRUE(body.is_static());
  return body;
}

// A ball or a box over the flat square's diagonal and its seam: the floor's normal only, one
// manifold, the box's four corners (each once, though two triangles hold each).
TEST(CollideMesh, OnAFlatSeamOnlyTheFloorsNormal) {
  const Body floor = floor_of(fold(0));
  for (const Vec3& at : {Vec3(0, 0.2, 0), Vec3(-0.5, 0.2, -0.5), Vec3(0.01, 0.2, 0.3)}) {
    const std::vector<Contact> ball = contacts(placed(Shape::sphere(0.2), at - Vec3(0, 0.001, 0)), floor);
    ASSERT_EQ(ball.size(), 1u) << at.transpose();
    EXPECT_NEAR(ball[0].normal.y(), 1, 1e-12);
    EXPECT_NEAR(ball[0].separation, -0.001, 1e-12);
  }
  const std::vector<Contact> box = contacts(placed(Shape::box({0.3, 0.2, 0.3}), {0.1, 0.199, 0.05}, about(Vec3::UnitY(), 30)), floor);
  ASSERT_EQ(box.size(), 4u);
  for (const Contact& c : box) {
    EXPECT_NEAR(c.normal.y(), 1, 1e-12);
    EXPECT_NEAR(c.separation, -0.001, 1e-9);
  }
}

// A box sliding into the valley's seam: the rising face's own normal where it meets it, never a
// normal of the seam's (which would lean between the two faces' and snag the box).
TEST(CollideMesh, IntoAValleyTheFacesNormals) {
  const Body floor = floor_of(fold(0.2));  // the second face rises at atan(0.2) = 11.3 degrees
  const Vec3 rising = Vec3(-0.2, 1, 0).normalized();
  // The box's right lower edge just touching the rising face beyond the seam.
  const Body box = placed(Shape::box({0.2, 0.1, 0.2}), {-0.18, 0.1, 0});
  const std::vector<Contact> found = contacts(box, floor, 0.05);
  ASSERT_FALSE(found.empty());
  for (const Contact& c : found) EXPECT_TRUE(c.normal.isApprox(Vec3::UnitY(), 1e-9) || c.normal.isApprox(rising, 1e-9)) << c.normal.transpose();
}

// Over a ridge a ball rounds the seam: its normal there is along the line from the seam to its centre.
TEST(CollideMesh, OverARidgeTheSeamsOwnNormal) {
  const Body floor = floor_of(fold(-0.5));
  const Vec3 centre(0.05, 0.2, 0.1);
  const std::vector<Contact> found = contacts(placed(Shape::sphere(0.21), centre), floor);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].normal.isApprox(Vec3(0.05, 0.2, 0).normalized(), 1e-9)) << found[0].normal.transpose();
  EXPECT_NEAR(found[0].separation, Vec3(0.05, 0.2, 0).norm() - 0.21, 1e-12);
}

// Nothing is touched from behind, and a far body touches nothing.
TEST(CollideMesh, BehindOrFarNothing) {
  const Body floor = floor_of(fold(0));
  EXPECT_TRUE(contacts(placed(Shape::sphere(0.2), {0.3, -0.15, 0.2}), floor).empty());
  EXPECT_TRUE(contacts(placed(Shape::sphere(0.2), {0.3, 0.5, 0.2}), floor).empty());
  EXPECT_TRUE(contacts(placed(Shape::box({0.2, 0.2, 0.2}), {3, 0.1, 0}), floor).empty());
}

}  // namespace
}  // namespace impulse::physics
