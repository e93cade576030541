// Golden images: fixed draw lists (no physics, so only the renderer can change them) drawn at
// 320x240 and compared with assets/golden/ (tests/support/golden_image.h has the tolerance and how to
// refresh them).
#include "render/overlay_painter.h"
#include "render/renderer.h"
#include "tests/support/golden_image.h"
#include "tests/support/render_scenes.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

using testing::bodies_scene;
using testing::lecture_overlay;

// Before any GL context (a static initialiser): the same bytes on every x86-64 machine.
[[maybe_unused]] const bool kPinned = [] {
  testing::pin_llvmpipe_for_goldens();
  return true;
}();

constexpr int kWidth = 320;
constexpr int kHeight = 240;

// Each test checks that the pin held (e.g. that no one set another width after it).
class Golden : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(testing::llvmpipe_pinned()) << "LP_NATIVE_VECTOR_WIDTH is not 128 for the goldens"; }
};

TEST_F(Golden, BodiesMarksAndGroundShadows) {
  render::Renderer renderer(kWidth, kHeight);
  EXPECT_MATCHES_GOLDEN("bodies", renderer.draw(bodies_scene()));
}

TEST_F(Golden, LectureOverlay) {
  render::Renderer renderer(kWidth, kHeight);
  render::Frame frame = renderer.draw(bodies_scene());
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(lecture_overlay(), frame);
  EXPECT_MATCHES_GOLDEN("overlay", frame);
}

TEST_F(Golden, TessellatedSpheresAndShadowMap) {
  render::RendererSettings settings;
  settings.spheres = render::SphereMethod::tessellated;
  settings.shadows = render::ShadowMethod::shadow_map;
  settings.shadow_map_size = 1024;
  render::Renderer renderer(kWidth, kHeight, settings);
  EXPECT_MATCHES_GOLDEN("tessellated_shadow_map", renderer.draw(bodies_scene()));
}

}  // namespace
}  // namespace impulse
