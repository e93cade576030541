// A transparent frame (RendererSettings::transparent): no sky, ground or ground shadow, the
// bodies as an opaque frame draws them, their outlines' coverage in alpha, and the overlay over it.
#include "render/frame.h"
#include "render/overlay_painter.h"
#include "render/renderer.h"
#include "tests/support/render_scenes.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

constexpr int kWidth = 320, kHeight = 240;

TEST(Transparent, TheSkyAndGroundAreLeftOutAndTheBodiesAreAsAnOpaqueFrameDrawsThem) {
  const render::DrawList scene = testing::bodies_scene();
  ASSERT_TRUE(scene.ground);
  render::Renderer opaque(kWidth, kHeight);
  const render::Frame ground = opaque.draw(scene);
  render::RendererSettings settings;
  settings.transparent = true;
  render::Renderer renderer(kWidth, kHeight, settings);
  const render::Frame frame = renderer.draw(scene);
  int clear = 0, solid = 0, partial = 0, same = 0, premultiplied = 0;
  for (size_t i = 0; i < frame.rgba.size(); i += 4) {
    const uint8_t* p = &frame.rgba[i];
    EXPECT_EQ(ground.rgba[i + 3], 255) << "an opaque frame is opaque everywhere, its marks' ghosts too";
    if (p[3] == 0) ++clear;
    else if (p[3] == 255) ++solid;
    else ++partial;
    if (p[3] == 255) same += p[0] == ground.rgba[i] && p[1] == ground.rgba[i + 1] && p[2] == ground.rgba[i + 2];
    premultiplied += p[0] <= p[3] && p[1] <= p[3] && p[2] <= p[3];
  }
  EXPECT_EQ(frame.rgba[3], 0) << "the sky's corner";
  EXPECT_EQ(frame.rgba[frame.rgba.size() - 1], 0) << "the ground's corner";
  EXPECT_GT(clear, kWidth * kHeight / 2) << "sky and ground left out";
  EXPECT_GT(solid, 2000) << "the bodies";
  EXPECT_GT(partial, 100) << "their outlines, and the marks' ghosts";
  EXPECT_GT(same, solid * 9 / 10) << "a body's inside as the opaque frame has it (its edge pixels mix in the sky there)";
  EXPECT_EQ(premultiplied, kWidth * kHeight) << "colour times alpha, until unpremultiply()";

  // The overlay over it: its boxes (nearly opaque, as over a video) over the transparent background.
  render::Frame overlaid = frame;
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(testing::lecture_overlay(), overlaid);
  int covered = 0, still_clear = 0;
  for (size_t i = 3; i < overlaid.rgba.size(); i += 4) {
    covered += overlaid.rgba[i] >= 200 && frame.rgba[i] == 0;
    still_clear += overlaid.rgba[i] == 0;
  }
  EXPECT_GT(covered, 2000) << "the overlay's boxes";
  EXPECT_GT(still_clear, kWidth * kHeight / 4) << "the rest left clear";
}

TEST(Transparent, UnpremultiplyGivesTheStraightColour) {
  render::Frame frame{2, 2, {100, 50, 0, 128, 7, 7, 7, 0, 10, 20, 30, 255, 255, 255, 255, 255}};
  render::unpremultiply(frame);
  EXPECT_EQ(frame.rgba, (std::vector<uint8_t>{199, 100, 0, 128, 0, 0, 0, 0, 10, 20, 30, 255, 255, 255, 255, 255}));
}

}  // namespace
}  // namespace impulse
