// Golden images: fixed draw lists (no physics, so only the renderer can change them) drawn at
// 320x240 and compared with assets/golden/ (tests/golden_image.h has the tolerance and how to
// refresh them).
#include "render/overlay_painter.h"
#include "render/renderer.h"
#include "tests/golden_image.h"
#include "tests/render_scenes.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

using testing::bodies_scene;
using testing::lecture_overlay;

// Before any GL context: the same bytes on every x86-64 machine.
const bool kPinned = [] {
  testing::pin_llvmpipe_for_goldens();
  return true;
}();

constexpr int kWidth = 320;
constexpr int kHeight = 240;

void expect_golden(const std::string& name, const render::Frame& frame) {
  const testing::GoldenResult result = testing::compare_with_golden(name, frame);
  EXPECT_TRUE(result.passed) << result.message;
}

TEST(Golden, BodiesMarksAndGroundShadows) {
  ASSERT_TRUE(kPinned);
  render::Renderer renderer(kWidth, kHeight);
  expect_golden("bodies", renderer.draw(bodies_scene()));
}

TEST(Golden, LectureOverlay) {
  render::Renderer renderer(kWidth, kHeight);
  render::Frame frame = renderer.draw(bodies_scene());
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(lecture_overlay(), frame);
  expect_golden("overlay", frame);
}

TEST(Golden, TessellatedSpheresAndShadowMap) {
  render::RendererSettings settings;
  settings.spheres = render::SphereMethod::tessellated;
  settings.shadows = render::ShadowMethod::shadow_map;
  settings.shadow_map_size = 1024;
  render::Renderer renderer(kWidth, kHeight, settings);
  expect_golden("tessellated_shadow_map", renderer.draw(bodies_scene()));
}

}  // namespace
}  // namespace impulse
