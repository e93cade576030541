// Hulls on film: what a frame draws of them (scene_draw_list.h: a render::MeshItem of their faces
// fanned into triangles), where the overlay keeps off them (body_boxes.h) and how large their marks
// may be (marks.h).
#include "demos/film/body_boxes.h"
#include "demos/film/marks.h"
#include "demos/film/scene_draw_list.h"
#include "physics/hull.h"
#include "render/camera_view.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>

namespace impulse {
namespace {

// A wedge (two triangles and three rectangles: 8 triangles) and a tetrahedron (4), each tilted and
// moving, the tetrahedron asleep, each in a colour of its own.
struct HullBodies {
  demos::Scene scene;
  std::vector<physics::Body> bodies{2};
  HullBodies() {
    bodies[0].shape = physics::Shape::convex(physics::place_hull(physics::wedge_points({1.2, 0.6, 0.8}), false).hull);
    bodies[0].position = physics::Vec3(1.0, 2.0, -0.5);
    bodies[0].orientation = physics::Quat(Eigen::AngleAxisd(0.5, physics::Vec3(1, 0, 1).normalized()));
    bodies[1].shape = physics::Shape::convex(physics::place_hull(physics::tetrahedron_points(0.9), false).hull);
    bodies[1].position = physics::Vec3(-1.0, 0.5, 0.0);
    bodies[1].orientation = physics::Quat(Eigen::AngleAxisd(std::numbers::pi / 3, physics::Vec3::UnitZ()));
    bodies[1].awake = false;
    for (physics::Body& body : bodies) body.inv_mass = 1;
    scene.colours = {{0.1f, 0.2f, 0.3f}, {0.7f, 0.6f, 0.5f}};
  }
  render::DrawList draw_list() const {
    return demos::scene_draw_list(scene, bodies, demos::poses_of(bodies), {}, {}, demos::ArrowScales{}, render::Camera{});
  }
};

// Each hull becomes one mesh at its body's place, in its colour and sleeping look, of its faces'
// triangles: as many as its faces' corners less two each, every corner one of the hull's, every
// triangle in its face's plane and counter-clockwise seen from outside (its normal the face's).
TEST(HullBodies, AHullIsAMeshOfItsFacesTriangles) {
  const HullBodies hulls;
  const render::DrawList list = hulls.draw_list();
  ASSERT_EQ(list.meshes.size(), 2u);
  EXPECT_TRUE(list.boxes.empty() && list.spheres.empty() && list.cylinders.empty());
  for (size_t i = 0; i < 2; ++i) {
    const physics::Body& body = hulls.bodies[i];
    const physics::Hull& hull = *body.shape.hull();
    const render::MeshItem& mesh = list.meshes[i];
    EXPECT_TRUE(mesh.centre.isApprox(body.position.cast<float>()));
    EXPECT_TRUE(mesh.orientation.isApprox(body.orientation.cast<float>()));
    EXPECT_EQ(mesh.sleeping, i == 1);
    EXPECT_FLOAT_EQ(mesh.colour.r, hulls.scene.colours[i].r);
    EXPECT_FLOAT_EQ(mesh.colour.b, hulls.scene.colours[i].b);

    ASSERT_TRUE(mesh.triangles);
    size_t expected = 0;
    for (const physics::HullFace& face : hull.faces) expected += size_t(face.count - 2);
    EXPECT_EQ(expected, i == 0 ? 8u : 4u);
    ASSERT_EQ(mesh.triangles->size(), 3 * expected);
    const std::vector<render::Vec3f>& corners = *mesh.triangles;
    for (size_t t = 0; t < expected; ++t) {
      const render::Vec3f a = corners[3 * t], b = corners[3 * t + 1], c = corners[3 * t + 2];
      const physics::Vec3 normal = (b - a).cross(c - a).cast<double>().normalized();
      const auto face = std::find_if(hull.faces.begin(), hull.faces.end(), [&](const physics::HullFace& f) {
        return f.normal.dot(normal) > 0.9999;
      });
      ASSERT_NE(face, hull.faces.end()) << "triangle " << t << " lies in no face, or faces in";
      for (const render::Vec3f& corner : {a, b, c}) {
        EXPECT_NEAR(face->normal.dot(corner.cast<double>()), face->offset, 1e-5) << "triangle " << t;
        EXPECT_TRUE(std::any_of(hull.corners.begin(), hull.corners.end(),
                                [&](const physics::Vec3& h) { return (h.cast<float>() - corner).norm() < 1e-6f; }));
      }
    }
    // Placed in the world, its corners are the body's: its lowest as low as the hull's lowest corner.
    float lowest = INFINITY;
    for (const render::Vec3f& corner : corners) lowest = std::min(lowest, (mesh.centre + mesh.orientation * corner).y());
    double hull_lowest = INFINITY;
    for (const physics::Vec3& corner : hull.corners) hull_lowest = std::min(hull_lowest, (body.position + body.orientation * corner).y());
    EXPECT_NEAR(lowest, hull_lowest, 1e-5);
  }
}

// The triangles are made once per hull: every frame, and every body of one hull, shares them (so
// the renderer uploads them once).
TEST(HullBodies, EveryFrameAndBodyOfOneHullSharesItsTriangles) {
  HullBodies hulls;
  hulls.bodies.push_back(hulls.bodies[0]);
  hulls.bodies[2].position.x() += 2;
  const render::DrawList first = hulls.draw_list();
  hulls.bodies[0].position.y() -= 0.1;
  const render::DrawList second = hulls.draw_list();
  ASSERT_EQ(first.meshes.size(), 3u);
  ASSERT_EQ(second.meshes.size(), 3u);
  EXPECT_EQ(first.meshes[0].triangles, second.meshes[0].triangles);
  EXPECT_EQ(first.meshes[1].triangles, second.meshes[1].triangles);
  EXPECT_EQ(first.meshes[0].triangles, first.meshes[2].triangles);
  EXPECT_NE(first.meshes[0].triangles, first.meshes[1].triangles);
}

// The box the overlay keeps off is the one round the hull's corners on screen: each corner in it,
// and each of its sides touched by one.
TEST(HullBodies, TheirScreenBoxesAreTheirCornersBoxes) {
  const HullBodies hulls;
  const render::CameraView view = render::make_camera_view(render::Camera{}, 1280, 720);
  std::vector<render::OverlayBody> boxes;
  demos::add_body_boxes(hulls.bodies, demos::poses_of(hulls.bodies), view, boxes);
  ASSERT_EQ(boxes.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const physics::Body& body = hulls.bodies[i];
    Eigen::Vector2f low = Eigen::Vector2f::Constant(INFINITY), high = Eigen::Vector2f::Constant(-INFINITY);
    for (const physics::Vec3& corner : body.shape.hull()->corners) {
      const auto at = view.to_pixels((body.position + body.orientation * corner).cast<float>());
      ASSERT_TRUE(at.has_value());
      low = low.cwiseMin(*at);
      high = high.cwiseMax(*at);
    }
    const render::ScreenBox& box = boxes[i].box;
    EXPECT_NEAR(box.x, low.x(), 1e-3f);
    EXPECT_NEAR(box.y, low.y(), 1e-3f);
    EXPECT_NEAR(box.right(), high.x(), 1e-3f);
    EXPECT_NEAR(box.bottom(), high.y(), 1e-3f);
    EXPECT_TRUE(boxes[i].moving);
  }
}

// A contact's dot and the automatic normals scale by a hull's thinnest half: its nearest face from
// its centre of mass (a regular tetrahedron's: its inradius, edge / sqrt(24)).
TEST(HullBodies, TheirSizeForMarksIsTheirNearestFace) {
  const physics::Shape tetrahedron = physics::Shape::convex(physics::place_hull(physics::tetrahedron_points(0.9), false).hull);
  EXPECT_NEAR(demos::body_size(tetrahedron), 0.9 / std::sqrt(24.0), 1e-9);
  EXPECT_DOUBLE_EQ(demos::body_size(tetrahedron), physics::thinnest_half_size(tetrahedron));
}

}  // namespace
}  // namespace impulse
