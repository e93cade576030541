// Planes on film (scene_draw_list.h): a horizontal one is the renderer's ground; any other (an
// incline, a ceiling) a thin slab in its colour, the static bodies' unless the scene says another,
// whose top face lies in the plane about the point nearest the camera's target.
#include "demos/film/render_types.h"
#include "demos/film/scene_draw_list.h"
#include "demos/scene/scene_sections.h"
#include "render/camera_view.h"
#include "render/renderer.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace impulse {
namespace {

using render::Vec3f;

// A 15-degree incline, its normal not of unit length (the plane is n.x = offset), and a ball
// resting on it at x = 0.
constexpr const char* kIncline = R"([camera]
position = [1, 3, 7]
target = [0, 0.8, 0]

[[body]]
name = "incline"
shape = "plane"
normal = [0.26, 0.97, 0]
offset = 0.5

[[body]]
name = "ball"
shape = "sphere"
radius = 0.3
position = [0.0777, 0.8053, 0]
colour = "#e69f00"
)";

demos::Scene scene_of(const std::string& name, const std::string& text) {
  return testing::scene_from(testing::scratch("plane_test", name), text);
}

render::DrawList draw_list_of(const demos::Scene& scene) {
  std::vector<physics::Body> bodies;
  for (const physics::BodyDef& def : scene.bodies) bodies.push_back(physics::make_body(def));
  return demos::scene_draw_list(scene, bodies, demos::poses_of(bodies), {}, {}, demos::ArrowScales{},
                                demos::to_render(scene.camera));
}

// The slab's top face: its four corners, and its centre.
struct TopFace {
  Vec3f corners[4];
  Vec3f centre;
  Vec3f up;
};
TopFace top_face(const render::BoxItem& slab) {
  const Vec3f h = slab.half_extents;
  TopFace face;
  face.up = slab.orientation * Vec3f::UnitY();
  face.centre = slab.centre + face.up * h.y();
  int i = 0;
  for (const float x : {-1.0f, 1.0f})
    for (const float z : {-1.0f, 1.0f}) face.corners[i++] = slab.centre + slab.orientation * Vec3f(x * h.x(), h.y(), z * h.z());
  return face;
}

// The incline is a box 2 cm thick: its top face in the plane and facing out of it, centred at the
// plane's point nearest the camera's target, at least 12 m across and as wide as the camera is far
// from its target, holding the point where the ball touches; in the static bodies' colour. No
// ground is drawn: the scene has none.
TEST(Planes, ATiltedPlaneIsASlabWhoseTopFaceLiesInIt) {
  const demos::Scene scene = scene_of("incline", kIncline);
  const render::DrawList list = draw_list_of(scene);
  EXPECT_FALSE(list.ground);
  ASSERT_EQ(list.boxes.size(), 1u);
  ASSERT_EQ(list.spheres.size(), 1u);
  const render::BoxItem& slab = list.boxes[0];
  const Vec3f normal = Vec3f(0.26f, 0.97f, 0.0f).normalized();
  const float offset = 0.5f / Vec3f(0.26f, 0.97f, 0.0f).norm();

  const TopFace face = top_face(slab);
  EXPECT_NEAR(face.up.dot(normal), 1.0f, 1e-6f);
  for (const Vec3f& corner : face.corners) EXPECT_NEAR(normal.dot(corner), offset, 1e-4f) << corner.transpose();
  EXPECT_NEAR(normal.dot(face.centre), offset, 1e-5f);
  EXPECT_LT((face.centre - list.camera.target).cross(normal).norm(), 1e-5f) << "nearest the target";
  EXPECT_NEAR(slab.half_extents.y(), 0.01f, 1e-6f);
  const float distance = (list.camera.position - list.camera.target).norm();
  EXPECT_GE(std::min(slab.half_extents.x(), slab.half_extents.z()), std::max(6.0f, distance) - 1e-5f);

  const render::SphereItem& ball = list.spheres[0];
  const Vec3f touching = slab.orientation.conjugate() * (ball.centre - ball.radius * normal - slab.centre);
  EXPECT_NEAR(touching.y(), slab.half_extents.y(), 1e-3f) << "the ball rests on the top face";
  EXPECT_LT(std::abs(touching.x()), slab.half_extents.x());
  EXPECT_LT(std::abs(touching.z()), slab.half_extents.z());

  EXPECT_FALSE(slab.sleeping);
  EXPECT_FLOAT_EQ(slab.colour.r, demos::kStaticColour.r);
  EXPECT_FLOAT_EQ(slab.colour.g, demos::kStaticColour.g);
  EXPECT_FLOAT_EQ(slab.colour.b, demos::kStaticColour.b);
}

// A ceiling (normal straight down) is a slab too, its top face down at the plane; a horizontal
// plane of any normal's length is the ground at its height, as ever, and no slab; a plane's own
// colour is the slab's.
TEST(Planes, AHorizontalPlaneIsTheGroundAndACeilingASlab) {
  const render::DrawList ground =
      draw_list_of(scene_of("ground", "[[body]]\nshape = \"plane\"\nnormal = [0, 2, 0]\noffset = 1\n"));
  EXPECT_TRUE(ground.ground);
  EXPECT_FLOAT_EQ(ground.ground_height, 0.5f);
  EXPECT_TRUE(ground.boxes.empty());

  const render::DrawList ceiling = draw_list_of(
      scene_of("ceiling", "[[body]]\nshape = \"plane\"\nnormal = [0, -1, 0]\noffset = -3\ncolour = \"#336699\"\n"));
  EXPECT_FALSE(ceiling.ground);
  ASSERT_EQ(ceiling.boxes.size(), 1u);
  const TopFace face = top_face(ceiling.boxes[0]);
  EXPECT_NEAR(face.up.y(), -1.0f, 1e-6f);
  for (const Vec3f& corner : face.corners) EXPECT_NEAR(corner.y(), 3.0f, 1e-5f) << corner.transpose();
  EXPECT_NEAR(face.centre.x(), ceiling.camera.target.x(), 1e-5f);
  EXPECT_NEAR(face.centre.z(), ceiling.camera.target.z(), 1e-5f);
  EXPECT_NEAR(ceiling.boxes[0].colour.b, 0x99 / 255.0f, 1e-6f);
}

// Drawn, the incline shows grey about the ball, unlike the sky, and the ball its own orange on it.
TEST(Planes, TheInclineIsDrawnAboutTheBall) {
  const demos::Scene scene = scene_of("drawn", kIncline);
  const render::DrawList list = draw_list_of(scene);
  render::Renderer renderer(320, 240);
  const render::Frame& frame = renderer.draw(list);
  const render::CameraView view = render::make_camera_view(list.camera, frame.width, frame.height);
  auto colour_at = [&](const Vec3f& world) {
    const auto at = view.to_pixels(world);
    EXPECT_TRUE(at.has_value());
    return testing::pixel(frame, std::clamp(int(at->x()), 0, frame.width - 1),
                          std::clamp(int(at->y()), 0, frame.height - 1));
  };
  const render::Colour& sky = list.background;
  auto unlike_sky = [&](const testing::Rgb& p) {
    return std::max({std::abs(p.r - int(std::lround(sky.r * 255))), std::abs(p.g - int(std::lround(sky.g * 255))),
                     std::abs(p.b - int(std::lround(sky.b * 255)))});
  };
  const Vec3f normal = Vec3f(0.26f, 0.97f, 0.0f).normalized();
  const Vec3f along = normal.cross(Vec3f::UnitZ()).normalized();  // down the slope, in the plane
  const Vec3f touching = list.spheres[0].centre - list.spheres[0].radius * normal;
  for (const Vec3f& on_plane : {Vec3f(touching + along), Vec3f(touching - along), Vec3f(touching + Vec3f::UnitZ())}) {
    const testing::Rgb p = colour_at(on_plane);
    EXPECT_GT(unlike_sky(p), 12) << on_plane.transpose();
    EXPECT_LT(std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b}), 20) << "grey at " << on_plane.transpose();
  }
  const testing::Rgb ball = colour_at(list.spheres[0].centre);
  EXPECT_GT(ball.r, ball.b + 60) << "the ball's own colour";
}

}  // namespace
}  // namespace impulse
