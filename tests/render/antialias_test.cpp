// Anti-aliasing measured as tests/bench/render_bench measures it: the mean colour error of a frame
// against its supersampled reference (render/antialias_reference.h), a frame drawn at sub-pixel
// offsets and averaged. The default (edge anti-aliasing) must be no worse than 4x multisampling,
// on a small frame with every kind of outline: spheres, boxes, arrows, points and ground shadows.
#include "render/antialias_reference.h"
#include "render/renderer.h"
#include "tests/support/render_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace impulse {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

double error_with(const render::RendererSettings& settings, const render::Frame& reference) {
  render::Renderer renderer(kWidth, kHeight, settings);
  return render::mean_colour_error(renderer.draw(testing::bodies_scene()), reference);
}

TEST(Antialiasing, TheDefaultIsNoWorseThanFourTimesMultisampling) {
  const render::RendererSettings defaults;
  ASSERT_EQ(defaults.antialiasing, render::Antialiasing::edges);
  render::RendererSettings msaa, none;
  msaa.antialiasing = render::Antialiasing::msaa;
  msaa.samples = 4;
  none.antialiasing = render::Antialiasing::none;
  for (const int grid : {4, 8}) {  // 16x, the bench's reference, and 64x
    const render::Frame reference = render::supersampled_reference(kWidth, kHeight, defaults, testing::bodies_scene(), grid);
    const double edges_error = error_with(defaults, reference);
    const double msaa_error = error_with(msaa, reference);
    const double none_error = error_with(none, reference);
    std::printf("mean colour error against %dx supersampling: edges %.4f, 4x MSAA %.4f, none %.4f\n", grid * grid,
                edges_error, msaa_error, none_error);
    EXPECT_LT(msaa_error, 0.6 * none_error) << "the measure sees anti-aliasing";
    EXPECT_LT(edges_error, 0.6 * none_error);
    EXPECT_LE(edges_error, msaa_error) << grid * grid << "x supersampled reference";
  }
}

// The offsets move the image as they say: moved by two whole pixels (an even number keeps llvmpipe's
// 2x2 pixel quads, whose differences shade the grid lines, as they were), the frame is the
// frame drawn without offset, two pixels further right (or down). (Without sleeping bodies: their
// hatching is in screen space and stays.)
TEST(Antialiasing, ASubpixelOffsetMovesTheImageByThatMuch) {
  render::DrawList scene = testing::bodies_scene();
  for (render::SphereItem& sphere : scene.spheres) sphere.sleeping = false;
  for (render::BoxItem& box : scene.boxes) box.sleeping = false;
  render::RendererSettings none;
  none.antialiasing = render::Antialiasing::none;
  render::Renderer renderer(kWidth, kHeight, none);
  const render::Frame still = renderer.draw(scene);
  auto moved_by = [&](float x, float y) {
    renderer.set_subpixel_offset(x, y);
    return renderer.draw(scene);
  };
  // Mean difference over the pixels that stay in the frame, of `moved` against `still` shifted by (dx, dy).
  auto mismatch = [&](const render::Frame& moved, int dx, int dy) {
    double total = 0;
    int count = 0;
    for (int y = 2; y + 2 < kHeight; ++y) {
      for (int x = 2; x + 2 < kWidth; ++x) {
        const uint8_t* a = moved.rgba.data() + 4 * size_t(y * kWidth + x);
        const uint8_t* b = still.rgba.data() + 4 * size_t((y - dy) * kWidth + (x - dx));
        for (int c = 0; c < 3; ++c) total += std::abs(int(a[c]) - int(b[c]));
        count += 3;
      }
    }
    return total / count;
  };
  const render::Frame right = moved_by(2.0f, 0.0f);
  const render::Frame down = moved_by(0.0f, 2.0f);
  EXPECT_LT(mismatch(right, 2, 0), 0.02);
  EXPECT_GT(mismatch(right, 0, 0), 1.0);
  EXPECT_LT(mismatch(down, 0, 2), 0.02);
  EXPECT_GT(mismatch(down, 0, 0), 1.0);
}

// 16 draws averaged: of a frame drawn the same each time, the same frame.
TEST(Antialiasing, TheReferenceOfAStillPictureIsThatPicture) {
  render::DrawList empty;  // sky and ground only: the grid lines move with the offsets, the sky does not
  empty.ground = false;
  render::RendererSettings none;
  none.antialiasing = render::Antialiasing::none;
  render::Renderer renderer(kWidth, kHeight, none);
  const render::Frame sky = renderer.draw(empty);
  EXPECT_EQ(render::mean_colour_error(render::supersampled_reference(kWidth, kHeight, {}, empty), sky), 0.0);
}

}  // namespace
}  // namespace impulse
