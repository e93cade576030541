// The renderer's marks: a contact's dot keeps to the bodies it marks.
#include "render/renderer.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

// Pixels darker than the background by far: the dot's core and most of its edge.
int dark_pixels(const render::Frame& frame) {
  int dark = 0;
  for (size_t i = 0; i < frame.rgba.size(); i += 4) dark += frame.rgba[i] < 100 && frame.rgba[i + 1] < 100 && frame.rgba[i + 2] < 100;
  return dark;
}

// A dot is `radius_pixels` on screen (8 px: about pi 8^2 = 201 pixels), but no larger than its
// `largest_radius` where it is: 0.1 m at 10 m with a 45-degree view of 240 lines is 2.9 px
// (about 26 pixels).
TEST(Points, ADotIsNoLargerThanItsLargestRadius) {
  constexpr int kWidth = 320, kHeight = 240;
  render::DrawList list;
  list.ground = false;
  list.camera.position = {0.0f, 0.0f, 10.0f};
  list.camera.target = {0.0f, 0.0f, 0.0f};
  list.points.push_back({render::Vec3f::Zero(), {0.0f, 0.0f, 0.0f}, 8.0f});
  render::Renderer renderer(kWidth, kHeight);
  const int free_dot = dark_pixels(renderer.draw(list));
  list.points[0].largest_radius = 0.1f;
  const int kept_dot = dark_pixels(renderer.draw(list));
  EXPECT_GT(free_dot, 150);
  EXPECT_LT(free_dot, 260);
  EXPECT_GT(kept_dot, 12);
  EXPECT_LT(kept_dot, 45);
}

}  // namespace
}  // namespace impulse
