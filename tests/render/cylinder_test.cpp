// Cylinders (CylinderItem, make_cylinder): an outward mesh, drawn where they project, round
// outlines seen end on, shadows on the ground by either method, outlines anti-aliased as well as
// every other body's, and spin marks that turn with them (a capsule's balls' among them).
#include "render/antialias_reference.h"
#include "render/camera_view.h"
#include "render/level_of_detail.h"
#include "render/mesh.h"
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

namespace impulse {
namespace {

using render::Vec3f;

constexpr int kWidth = 640;
constexpr int kHeight = 480;
constexpr float kPi = std::numbers::pi_v<float>;

const uint8_t* pixel(const render::Frame& frame, int x, int y) { return frame.rgba.data() + 4 * (size_t(y) * frame.width + x); }

int difference(const uint8_t* a, const uint8_t* b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// The pixel where `world` lands (rounded down: the pixel holding that point).
const uint8_t* pixel_at(const render::Frame& frame, const render::DrawList& list, const Vec3f& world) {
  const auto at = render::make_camera_view(list.camera, frame.width, frame.height).to_pixels(world);
  EXPECT_TRUE(at.has_value());
  const int x = std::clamp(int(std::floor(at->x())), 0, frame.width - 1), y = std::clamp(int(std::floor(at->y())), 0, frame.height - 1);
  return pixel(frame, x, y);
}

bool is_background(const uint8_t* p, const render::Colour& background) {
  const uint8_t expected[3] = {uint8_t(std::lround(background.r * 255)), uint8_t(std::lround(background.g * 255)),
                               uint8_t(std::lround(background.b * 255))};
  return difference(p, expected) <= 1;
}

bool is_red(const uint8_t* p) { return p[0] > p[1] + 60 && p[0] > p[2] + 60; }

// The silhouette's width, pixels, along the line through (x, y) with step (dx, dy), over a plain
// background: the run of pixels unlike the background, its two end pixels counted by how far they
// are from the background towards the pixel inside them (an outline's pixel mixes the two), scaled
// by the step's length.
double width_through(const render::Frame& frame, int x, int y, int dx, int dy) {
  const uint8_t* background = pixel(frame, 0, 0);
  auto inside = [&](int i) {
    const int px = x + i * dx, py = y + i * dy;
    return px >= 0 && py >= 0 && px < frame.width && py < frame.height && difference(pixel(frame, px, py), background) > 4;
  };
  int first = 0, last = 0;
  while (inside(first - 1)) --first;
  while (inside(last + 1)) ++last;
  auto coverage = [&](int end, int inner) {
    const uint8_t* inner_pixel = pixel(frame, x + inner * dx, y + inner * dy);
    return std::min(1.0, double(difference(pixel(frame, x + end * dx, y + end * dy), background)) /
                             std::max(1, difference(inner_pixel, background)));
  };
  return (last - first - 1 + coverage(first, first + 1) + coverage(last, last - 1)) * std::hypot(double(dx), double(dy));
}

render::Quatf lying_along_x() { return render::Quatf(Eigen::AngleAxisf(-kPi / 2, Vec3f::UnitZ())); }

render::CylinderItem red_cylinder(const Vec3f& centre, float radius, float half_height,
                                  const render::Quatf& orientation = render::Quatf::Identity()) {
  render::CylinderItem cylinder;
  cylinder.centre = centre;
  cylinder.radius = radius;
  cylinder.half_height = half_height;
  cylinder.orientation = orientation;
  cylinder.colour = {0.85f, 0.2f, 0.15f};
  return cylinder;
}

// Radius 1, y in [-1, 1]; every triangle faces out (counter-clockwise seen from outside, as
// GL_CULL_FACE keeps); the side's normals are horizontal and unit, the caps' straight up or down.
TEST(Cylinders, TheMeshIsTheUnitCylinderFacingOutwards) {
  const render::MeshData mesh = render::make_cylinder(render::kCylinderSegments);
  EXPECT_EQ(mesh.indices.size(), 3u * 4u * size_t(render::kCylinderSegments));
  int side = 0, caps = 0;
  for (const render::MeshVertex& v : mesh.vertices) {
    const Vec3f p(v.position[0], v.position[1], v.position[2]), n(v.normal[0], v.normal[1], v.normal[2]);
    EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
    EXPECT_LE(std::abs(p.y()), 1.0f);
    if (std::abs(n.y()) > 0.5f) {  // a cap: at its face, inside the unit circle
      ++caps;
      EXPECT_EQ(p.y(), n.y());
      EXPECT_LE(std::hypot(p.x(), p.z()), 1.0f + 1e-5f);
    } else {  // the side: on the unit circle, the normal straight out
      ++side;
      EXPECT_EQ(std::abs(p.y()), 1.0f);
      EXPECT_NEAR(std::hypot(p.x(), p.z()), 1.0f, 1e-5f);
      EXPECT_EQ(n.y(), 0.0f);
      EXPECT_NEAR(n.x(), p.x(), 1e-6f);
      EXPECT_NEAR(n.z(), p.z(), 1e-6f);
    }
  }
  EXPECT_EQ(side, 2 * render::kCylinderSegments);
  EXPECT_EQ(caps, 2 * (render::kCylinderSegments + 1));
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    auto at = [&](size_t k) { const float* p = mesh.vertices[mesh.indices[i + k]].position; return Vec3f(p[0], p[1], p[2]); };
    const Vec3f a = at(0), b = at(1), c = at(2);
    const Vec3f facing = (b - a).cross(c - a);
    EXPECT_GT(facing.norm(), 1e-4f) << "triangle " << i / 3 << " has no area";
    EXPECT_GT(facing.dot((a + b + c) / 3.0f), 0.0f) << "triangle " << i / 3 << " faces in";
  }
}

// A standing cylinder seen from straight above shows its top cap: a circle of radius f r / d
// pixels, as wide across as down and along both diagonals (a polygon of few sides, or outline
// values of a box, would not be); red there, the background outside it.
TEST(Cylinders, AStandingCylinderSeenFromAboveIsARoundDisc) {
  render::DrawList list;
  list.ground = false;
  list.camera.position = {0.0f, 5.0f, 0.0f};
  list.camera.target = Vec3f::Zero();
  list.cylinders.push_back(red_cylinder(Vec3f::Zero(), 1.0f, 0.5f));
  render::Renderer renderer(kWidth, kHeight);
  const render::Frame& frame = renderer.draw(list);

  const render::CameraView view = render::make_camera_view(list.camera, kWidth, kHeight);
  const double diameter = 2.0 * view.focal_pixels * 1.0 / (5.0 - 0.5);  // the top cap, 4.5 m away
  const int cx = kWidth / 2, cy = kHeight / 2;
  ASSERT_TRUE(is_red(pixel(frame, cx, cy)));
  const double across = width_through(frame, cx, cy, 1, 0), down = width_through(frame, cx, cy, 0, 1);
  const double diagonal = width_through(frame, cx, cy, 1, 1), other_diagonal = width_through(frame, cx, cy, 1, -1);
  std::printf("silhouette %.2f px across, %.2f down, %.2f and %.2f diagonally; a circle's %.2f\n", across, down,
              diagonal, other_diagonal, diameter);
  EXPECT_NEAR(across, diameter, 1.0);
  EXPECT_NEAR(down, diameter, 1.0);
  EXPECT_NEAR(across, down, 1.0);
  EXPECT_NEAR(diagonal, diameter, 2.0);
  EXPECT_NEAR(other_diagonal, diameter, 2.0);

  for (const float angle : {0.0f, 0.7f, 2.0f, 4.0f}) {
    const Vec3f direction(std::cos(angle), 0.0f, std::sin(angle));
    EXPECT_TRUE(is_red(pixel_at(frame, list, 0.5f * Vec3f::UnitY() + 0.95f * direction))) << "inside the rim at " << angle;
    EXPECT_TRUE(is_background(pixel_at(frame, list, 0.5f * Vec3f::UnitY() + 1.05f * direction), list.background))
        << "outside the rim at " << angle;
  }
}

// Lying along x: end on, its near cap is a circle; side on, its outline is as wide as its rims'
// nearest points and as tall as the tangents from the eye to its side.
TEST(Cylinders, ALyingCylinderIsRoundEndOnAndAsLongAndTallAsItsSideSideOn) {
  render::DrawList list;
  list.ground = false;
  list.camera.target = {0.0f, 0.5f, 0.0f};
  list.cylinders.push_back(red_cylinder({0.0f, 0.5f, 0.0f}, 0.5f, 1.0f, lying_along_x()));
  render::Renderer renderer(kWidth, kHeight);
  const int cx = kWidth / 2, cy = kHeight / 2;
  const float focal = render::make_camera_view(list.camera, kWidth, kHeight).focal_pixels;

  list.camera.position = {6.0f, 0.5f, 0.0f};  // end on: the cap at x = 1 is 5 m away
  const render::Frame end_on = renderer.draw(list);
  ASSERT_TRUE(is_red(pixel(end_on, cx, cy)));
  const double cap = 2.0 * focal * 0.5 / 5.0;
  const double across = width_through(end_on, cx, cy, 1, 0), down = width_through(end_on, cx, cy, 0, 1);
  std::printf("end on: %.2f px across, %.2f down; a circle's %.2f\n", across, down, cap);
  EXPECT_NEAR(across, cap, 1.0);
  EXPECT_NEAR(down, cap, 1.0);
  EXPECT_NEAR(width_through(end_on, cx, cy, 1, 1), cap, 2.0);

  list.camera.position = {0.0f, 0.5f, 6.0f};  // side on
  const render::Frame side_on = renderer.draw(list);
  ASSERT_TRUE(is_red(pixel(side_on, cx, cy)));
  const double length = 2.0 * focal * 1.0 / 5.5;                            // the rims' nearest points
  const double height = 2.0 * focal * 0.5 / std::sqrt(6.0 * 6.0 - 0.5 * 0.5);  // tangents to the side
  const double long_way = width_through(side_on, cx, cy, 1, 0), short_way = width_through(side_on, cx, cy, 0, 1);
  std::printf("side on: %.2f px long (%.2f expected), %.2f tall (%.2f expected)\n", long_way, length, short_way, height);
  EXPECT_NEAR(long_way, length, 1.0);
  EXPECT_NEAR(short_way, height, 1.0);
  for (const float x : {-0.9f, 0.0f, 0.9f}) EXPECT_TRUE(is_red(pixel_at(side_on, list, {x, 0.5f, 0.5f}))) << x;
  for (const Vec3f& outside : {Vec3f(1.1f, 0.5f, 0.5f), Vec3f(-1.1f, 0.5f, 0.5f), Vec3f(0.0f, 1.1f, 0.0f), Vec3f(0.0f, -0.1f, 0.0f)})
    EXPECT_TRUE(is_background(pixel_at(side_on, list, outside), list.background)) << outside.transpose();
}

// A cylinder held up in a light from 45 degrees casts a shadow on the ground, away from the light:
// its caps' shadows are discs of its radius 1.2 m and 1.8 m along -x (their heights), joined by
// the side's. Both shadow methods put it there, and leave the ground lit beside it.
TEST(Cylinders, CastAShadowOnTheGroundByEitherMethod) {
  render::DrawList list;
  list.camera.position = {0.0f, 4.0f, 7.0f};
  list.camera.target = {-0.5f, 0.5f, 0.0f};
  list.towards_light = {1.0f, 1.0f, 0.0f};
  list.cylinders.push_back(red_cylinder({0.0f, 1.5f, 0.0f}, 0.4f, 0.3f));
  const Vec3f in_shadow[] = {{-1.5f, 0.0f, 0.15f}, {-1.25f, 0.0f, -0.2f}, {-1.9f, 0.0f, 0.1f}};
  const Vec3f lit[] = {{1.5f, 0.0f, 0.15f}, {-1.5f, 0.0f, 0.7f}, {-2.4f, 0.0f, 0.15f}, {-0.6f, 0.0f, 0.15f}};
  for (const render::ShadowMethod method : {render::ShadowMethod::ground, render::ShadowMethod::shadow_map}) {
    render::RendererSettings settings;
    settings.shadows = method;
    render::Renderer renderer(kWidth, kHeight, settings);
    const render::Frame& frame = renderer.draw(list);
    const bool map = method == render::ShadowMethod::shadow_map;
    ASSERT_TRUE(is_red(pixel_at(frame, list, {0.0f, 1.5f, 0.4f}))) << "map " << map;
    auto brightness = [&](const Vec3f& at) {
      const uint8_t* p = pixel_at(frame, list, at);
      return int(p[0]) + int(p[1]) + int(p[2]);
    };
    const int lit_ground = brightness(lit[0]);
    for (const Vec3f& at : lit) EXPECT_NEAR(brightness(at), lit_ground, 24) << "lit at " << at.transpose() << ", map " << map;
    for (const Vec3f& at : in_shadow)
      EXPECT_LT(brightness(at), 0.8 * lit_ground) << "shadowed at " << at.transpose() << ", map " << map;
  }
}

// A marked red is at most this share of the unmarked (the shader darkens the albedo to 0.74 in
// linear light: about 0.86 on screen).
constexpr float kMarkedAtMost = 0.92f;

// Whether spin marks darken `world` on a body at `centre` turned by `orientation`: the octant
// shader's rule (kSurface, octant_shade) in the body's own frame.
bool marked_dark(const Vec3f& world, const Vec3f& centre, const render::Quatf& orientation) {
  const Vec3f local = orientation.conjugate() * (world - centre);
  return local.x() * local.y() * local.z() >= 0.0f;
}

// The point of the side of a cylinder lying along x about y = 0.5 at `x`, `radius` from its axis and
// `degrees` round it from +z (towards the eye) towards +y.
Vec3f on_side(float x, float radius, float degrees) {
  const float angle = degrees * kPi / 180.0f;
  return {x, 0.5f + radius * std::sin(angle), radius * std::cos(angle)};
}

// A cylinder lying along x, seen side on in a light that is the same either side of x = 0, turned
// 0 and 45 degrees about its axis: spin-marked, a point of its side changes between dark and light
// where its octant of the cylinder's frame changes, and otherwise keeps its colour (45 degrees is 8
// of the mesh's 64 sides: the same facets, so the same shading); the halves either side of its
// middle are marked oppositely. Unmarked, it looks the same turned or not and either side of its
// middle: one colour up to shading.
TEST(Cylinders, SpinMarksTurnWithTheCylinderAboutItsAxis) {
  render::DrawList list;
  list.ground = false;
  list.towards_light = {0.0f, 1.0f, 0.35f};
  list.camera.position = {0.0f, 0.5f, 6.0f};
  list.camera.target = {0.0f, 0.5f, 0.0f};
  render::Renderer renderer(kWidth, kHeight);
  const Vec3f centre(0.0f, 0.5f, 0.0f);
  auto turned = [](float degrees) {
    return render::Quatf(Eigen::AngleAxisf(degrees * kPi / 180.0f, Vec3f::UnitX())) * lying_along_x();
  };
  auto frame_of = [&](float degrees, bool spin_marks) {
    render::CylinderItem cylinder = red_cylinder(centre, 0.5f, 1.0f, turned(degrees));
    cylinder.spin_marks = spin_marks;
    list.cylinders = {cylinder};
    return renderer.draw(list);
  };
  // Mid-sector at either turn (every boundary is at a multiple of 45 degrees), both halves.
  std::vector<Vec3f> points;
  for (const float x : {-0.5f, 0.5f})
    for (const float degrees : {-67.5f, -22.5f, 22.5f, 67.5f}) points.push_back(on_side(x, 0.5f, degrees));

  const render::Frame marked = frame_of(0.0f, true), marked_turned = frame_of(45.0f, true);
  const render::Frame plain = frame_of(0.0f, false), plain_turned = frame_of(45.0f, false);
  int changed = 0;
  for (const Vec3f& at : points) {
    const uint8_t *before = pixel_at(marked, list, at), *after = pixel_at(marked_turned, list, at);
    ASSERT_TRUE(is_red(before) && is_red(after)) << at.transpose();
    const bool dark_before = marked_dark(at, centre, turned(0.0f)), dark_after = marked_dark(at, centre, turned(45.0f));
    std::printf("(%5.2f, %5.2f, %5.2f): red %3d -> %3d (%s -> %s)\n", at.x(), at.y(), at.z(), before[0], after[0],
                dark_before ? "dark" : "light", dark_after ? "dark" : "light");
    if (dark_before == dark_after) {
      EXPECT_LE(difference(before, after), 2) << "unmoved mark at " << at.transpose();
    } else {
      ++changed;
      const uint8_t *dark = dark_before ? before : after, *light = dark_before ? after : before;
      EXPECT_LT(dark[0], kMarkedAtMost * light[0]) << "moved mark at " << at.transpose();
    }
    // The mirror image across the middle: the other half, marked the other way.
    const Vec3f mirrored(-at.x(), at.y(), at.z());
    const int red = before[0], mirrored_red = pixel_at(marked, list, mirrored)[0];
    EXPECT_LT(std::min(red, mirrored_red), kMarkedAtMost * std::max(red, mirrored_red)) << at.transpose();

    EXPECT_LE(difference(pixel_at(plain, list, at), pixel_at(plain_turned, list, at)), 1) << "plain at " << at.transpose();
    EXPECT_LE(difference(pixel_at(plain, list, at), pixel_at(plain, list, mirrored)), 2) << "plain at " << at.transpose();
  }
  EXPECT_EQ(changed, 4);
}

// A capsule (a cylinder lying along x and a ball at each end, all in its orientation, turned 90
// degrees about its axis): just beyond either end, the ball is dark or light as the cylinder just
// inside it, round the side, where the two surfaces' normals are nearly the same (the light from
// the front keeps the highlight off the points compared, and they are well inside the outline); and
// at each angle one ball is dark where the other is light, as the cylinder's halves are.
TEST(Cylinders, ACapsulesBallsContinueItsCylindersMarks) {
  render::DrawList list;
  list.ground = false;
  list.towards_light = {0.0f, 0.35f, 1.0f};
  list.camera.position = {0.0f, 0.5f, 6.0f};
  list.camera.target = {0.0f, 0.5f, 0.0f};
  const Vec3f centre(0.0f, 0.5f, 0.0f);
  const float radius = 0.3f, half_height = 0.6f, gap = 0.04f;
  const render::Quatf orientation = render::Quatf(Eigen::AngleAxisf(kPi / 2.0f, Vec3f::UnitX())) * lying_along_x();
  list.cylinders.push_back(red_cylinder(centre, radius, half_height, orientation));
  for (const float end : {-1.0f, 1.0f})
    list.spheres.push_back({centre + orientation * Vec3f(0.0f, end * half_height, 0.0f), radius, orientation,
                            list.cylinders[0].colour});
  render::Renderer renderer(kWidth, kHeight);
  const render::Frame& frame = renderer.draw(list);

  int ball_red[2][2] = {};  // by end and angle
  for (const float end : {-1.0f, 1.0f})
    for (const float degrees : {-45.0f, 45.0f}) {  // mid-sector: the boundaries are at 90 k degrees
      const Vec3f on_cylinder = on_side(end * (half_height - gap), radius, degrees);
      const Vec3f on_ball = on_side(end * (half_height + gap), std::sqrt(radius * radius - gap * gap), degrees);
      const uint8_t *cylinder = pixel_at(frame, list, on_cylinder), *ball = pixel_at(frame, list, on_ball);
      ASSERT_TRUE(is_red(cylinder) && is_red(ball)) << on_ball.transpose();
      const bool is_dark = marked_dark(on_cylinder, centre, orientation);
      std::printf("end %+.0f at %5.1f degrees: cylinder %3d %3d %3d, ball %3d %3d %3d (%s)\n", end, degrees, cylinder[0],
                  cylinder[1], cylinder[2], ball[0], ball[1], ball[2], is_dark ? "dark" : "light");
      EXPECT_LE(difference(cylinder, ball), 6) << on_ball.transpose();
      ball_red[end > 0][degrees > 0] = ball[0];
    }
  for (int angle = 0; angle < 2; ++angle) {
    const int a = ball_red[0][angle], b = ball_red[1][angle];
    EXPECT_LT(std::min(a, b), kMarkedAtMost * std::max(a, b)) << "angle " << angle;
  }
}

// The drawn outlines are as smooth as the other bodies' (antialias_test.cpp): the default's mean
// colour error against a 64x supersampled frame no worse than 4x multisampling's, on standing,
// lying and tilted cylinders, a capsule (a cylinder and two spheres) and their ground shadows.
TEST(Cylinders, TheirOutlinesAreAntialiasedAsWellAsFourTimesMultisampling) {
  constexpr int kSmallWidth = 320, kSmallHeight = 240;
  render::DrawList list;
  list.camera.position = {0.0f, 2.5f, 6.0f};
  list.camera.target = {0.0f, 0.6f, 0.0f};
  list.cylinders.push_back(red_cylinder({-1.8f, 0.6f, 0.0f}, 0.45f, 0.6f));
  list.cylinders.push_back(red_cylinder({0.2f, 0.35f, 0.8f}, 0.35f, 0.9f, lying_along_x()));
  list.cylinders.push_back(red_cylinder({1.6f, 1.3f, -0.5f}, 0.3f, 0.5f,
                                        render::Quatf(Eigen::AngleAxisf(0.6f, Vec3f(1.0f, 0.0f, 1.0f).normalized()))));
  const render::Quatf tilt(Eigen::AngleAxisf(1.1f, Vec3f::UnitZ()));
  render::CylinderItem capsule = red_cylinder({0.0f, 1.6f, -1.0f}, 0.25f, 0.5f, tilt);
  capsule.colour = {0.2f, 0.45f, 0.8f};
  list.cylinders.push_back(capsule);
  for (const float end : {-1.0f, 1.0f})
    list.spheres.push_back({capsule.centre + tilt * Vec3f(0.0f, end * capsule.half_height, 0.0f), capsule.radius, tilt,
                            capsule.colour});

  const render::RendererSettings defaults;
  render::RendererSettings msaa, none;
  msaa.antialiasing = render::Antialiasing::msaa;
  none.antialiasing = render::Antialiasing::none;
  const render::Frame reference = render::supersampled_reference(kSmallWidth, kSmallHeight, defaults, list, 8);
  auto error_with = [&](const render::RendererSettings& settings) {
    render::Renderer renderer(kSmallWidth, kSmallHeight, settings);
    return render::mean_colour_error(renderer.draw(list), reference);
  };
  const double edges_error = error_with(defaults), msaa_error = error_with(msaa), none_error = error_with(none);
  std::printf("mean colour error against 64x supersampling: edges %.4f, 4x MSAA %.4f, none %.4f\n", edges_error,
              msaa_error, none_error);
  EXPECT_LT(edges_error, 0.6 * none_error);
  EXPECT_LE(edges_error, msaa_error);
}

}  // namespace
}  // namespace impulse
