// Cylinders and capsules on film: what a frame draws of them (scene_draw_list.h), where the overlay
// keeps off them (body_boxes.h) and how large their marks may be (marks.h).
#include "demos/film/body_boxes.h"
#include "demos/film/marks.h"
#include "demos/film/scene_draw_list.h"
#include "render/camera_view.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

namespace impulse {
namespace {

// A capsule and a cylinder, each tilted and moving, the capsule asleep, each in a colour of its own.
struct RoundBodies {
  demos::Scene scene;
  std::vector<physics::Body> bodies{2};
  RoundBodies() {
    bodies[0].shape = physics::Shape::capsule(0.2, 0.6);
    bodies[0].position = physics::Vec3(1.0, 2.0, -0.5);
    bodies[0].orientation = physics::Quat(Eigen::AngleAxisd(0.5, physics::Vec3(1, 0, 1).normalized()));
    bodies[0].awake = false;
    bodies[1].shape = physics::Shape::cylinder(0.3, 0.25);
    bodies[1].position = physics::Vec3(-1.0, 0.5, 0.0);
    bodies[1].orientation = physics::Quat(Eigen::AngleAxisd(std::numbers::pi / 2, physics::Vec3::UnitZ()));
    for (physics::Body& body : bodies) body.inv_mass = 1;
    scene.colours = {{0.1f, 0.2f, 0.3f}, {0.7f, 0.6f, 0.5f}};
  }
  render::DrawList draw_list() const {
    return demos::scene_draw_list(scene, bodies, demos::poses_of(bodies), {}, {}, demos::ArrowScales{}, render::Camera{});
  }
};

void expect_colour(const render::Colour& colour, const demos::Colour& expected) {
  EXPECT_FLOAT_EQ(colour.r, expected.r);
  EXPECT_FLOAT_EQ(colour.g, expected.g);
  EXPECT_FLOAT_EQ(colour.b, expected.b);
}

// A capsule becomes the cylinder of its segment and a ball of its radius at each end, along its
// rotated y axis, in its colour and sleeping look, all spin-marked in its orientation (so the balls'
// marks turn with it); a cylinder becomes one spin-marked cylinder.
TEST(RoundBodies, ACapsuleIsACylinderAndTwoBallsAndACylinderIsOne) {
  const RoundBodies round;
  const render::DrawList list = round.draw_list();
  ASSERT_EQ(list.cylinders.size(), 2u);
  ASSERT_EQ(list.spheres.size(), 2u);
  EXPECT_TRUE(list.boxes.empty());

  const physics::Body& capsule = round.bodies[0];
  const render::CylinderItem& segment = list.cylinders[0];
  EXPECT_TRUE(segment.centre.isApprox(capsule.position.cast<float>()));
  EXPECT_FLOAT_EQ(segment.radius, 0.2f);
  EXPECT_FLOAT_EQ(segment.half_height, 0.6f);
  EXPECT_TRUE(segment.orientation.isApprox(capsule.orientation.cast<float>()));
  EXPECT_TRUE(segment.spin_marks);
  EXPECT_TRUE(segment.sleeping);
  expect_colour(segment.colour, round.scene.colours[0]);
  const physics::Vec3 axis = capsule.orientation * physics::Vec3::UnitY();
  for (const render::SphereItem& ball : list.spheres) {
    EXPECT_FLOAT_EQ(ball.radius, 0.2f);
    EXPECT_TRUE(ball.spin_marks);
    EXPECT_TRUE(ball.orientation.isApprox(segment.orientation));
    EXPECT_TRUE(ball.sleeping);
    expect_colour(ball.colour, round.scene.colours[0]);
    // On the axis, 0.6 m from the centre.
    const physics::Vec3 offset = ball.centre.cast<double>() - capsule.position;
    EXPECT_NEAR(std::abs(offset.dot(axis)), 0.6, 1e-6);
    EXPECT_NEAR((offset - offset.dot(axis) * axis).norm(), 0.0, 1e-6);
  }
  EXPECT_NEAR((list.spheres[0].centre + list.spheres[1].centre).cast<double>().x() / 2, capsule.position.x(), 1e-6)
      << "one at each end";
  EXPECT_NEAR((list.spheres[0].centre - list.spheres[1].centre).norm(), 1.2f, 1e-6f);

  const render::CylinderItem& cylinder = list.cylinders[1];
  EXPECT_TRUE(cylinder.centre.isApprox(round.bodies[1].position.cast<float>()));
  EXPECT_FLOAT_EQ(cylinder.radius, 0.3f);
  EXPECT_FLOAT_EQ(cylinder.half_height, 0.25f);
  EXPECT_TRUE(cylinder.orientation.isApprox(round.bodies[1].orientation.cast<float>()));
  EXPECT_TRUE(cylinder.spin_marks);
  EXPECT_FALSE(cylinder.sleeping);
  expect_colour(cylinder.colour, round.scene.colours[1]);
}

// The box the overlay keeps off holds every point of the body's surface on screen: a capsule's
// ends (its caps' far points along the axis) and a cylinder's rims.
TEST(RoundBodies, TheirScreenBoxesHoldTheirEndsAndRims) {
  const RoundBodies round;
  const render::CameraView view = render::make_camera_view(render::Camera{}, 1280, 720);
  std::vector<render::OverlayBody> boxes;
  demos::add_body_boxes(round.bodies, demos::poses_of(round.bodies), view, boxes);
  ASSERT_EQ(boxes.size(), 2u);
  auto holds = [&](const render::ScreenBox& box, const physics::Vec3& point) {
    const auto at = view.to_pixels(point.cast<float>());
    return at && at->x() >= box.x - 1e-3f && at->x() <= box.right() + 1e-3f && at->y() >= box.y - 1e-3f &&
           at->y() <= box.bottom() + 1e-3f;
  };
  const physics::Body& capsule = round.bodies[0];
  const physics::Vec3 axis = capsule.orientation * physics::Vec3::UnitY();
  for (const double end : {-0.8, 0.8}) EXPECT_TRUE(holds(boxes[0].box, capsule.position + end * axis)) << end;
  const physics::Body& cylinder = round.bodies[1];
  for (int i = 0; i < 16; ++i) {
    const double angle = 2 * std::numbers::pi * i / 16;
    for (const double y : {-0.25, 0.25}) {
      const physics::Vec3 rim(0.3 * std::cos(angle), y, 0.3 * std::sin(angle));
      EXPECT_TRUE(holds(boxes[1].box, cylinder.position + cylinder.orientation * rim)) << angle << " " << y;
    }
  }
  // And no larger than the box round the body in its own frame needs: the cylinder lies along x,
  // 0.5 m long and 0.6 m across, 10 m away.
  EXPECT_LT(boxes[1].box.w, 1.2f * 0.6f * view.pixels_per_metre(cylinder.position.cast<float>()));
}

// A contact's dot and the automatic normals scale by a body's size: a capsule's radius, the
// smaller of a cylinder's radius and half height.
TEST(RoundBodies, TheirSizeForMarksIsTheirThinnestHalf) {
  EXPECT_DOUBLE_EQ(demos::body_size(physics::Shape::capsule(0.2, 0.6)), 0.2);
  EXPECT_DOUBLE_EQ(demos::body_size(physics::Shape::capsule(0.5, 0.1)), 0.5);
  EXPECT_DOUBLE_EQ(demos::body_size(physics::Shape::cylinder(0.3, 0.25)), 0.25);
  EXPECT_DOUBLE_EQ(demos::body_size(physics::Shape::cylinder(0.1, 0.25)), 0.1);
}

}  // namespace
}  // namespace impulse
