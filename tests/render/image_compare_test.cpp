// The pixel comparison of `impulse verify` and the golden tests (render/image_compare.h): the
// perceptual distance, anti-aliased edges forgiven, and regions of differing pixels counted.
#include "render/image_compare.h"

#include <cmath>

#include <gtest/gtest.h>

namespace impulse {
namespace {

using render::Frame;

Frame plain(int width, int height, uint8_t grey) {
  Frame frame;
  render::fill(frame, width, height, render::Colour{grey / 255.0f, grey / 255.0f, grey / 255.0f});
  return frame;
}

void set(Frame& frame, int x, int y, uint8_t r, uint8_t g, uint8_t b) {
  uint8_t* pixel = frame.rgba.data() + (size_t(y) * frame.width + x) * 4;
  pixel[0] = r, pixel[1] = g, pixel[2] = b;
}

// Black left of column `edge`, white right of it, and the edge column grey `edge_grey`: an
// anti-aliased vertical edge.
Frame edge_frame(int edge, uint8_t edge_grey) {
  Frame frame = plain(40, 30, 255);
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < edge; ++x) set(frame, x, y, 0, 0, 0);
    set(frame, edge, y, edge_grey, edge_grey, edge_grey);
  }
  return frame;
}

TEST(ImageCompare, BlackAgainstWhiteIsNearlyTheWholeScale) {
  const uint8_t black[3] = {0, 0, 0}, white[3] = {255, 255, 255}, grey[3] = {128, 128, 128};
  EXPECT_NEAR(render::colour_distance(black, white), std::sqrt(0.5053 * 255 * 255 / 35215), 1e-6);  // luma only
  const uint8_t blue[3] = {0, 0, 255}, yellow[3] = {255, 255, 0};
  EXPECT_LE(render::colour_distance(blue, yellow), 1.0);
  EXPECT_EQ(render::colour_distance(grey, grey), 0.0);
  const uint8_t near_grey[3] = {131, 128, 126};
  EXPECT_LT(render::colour_distance(grey, near_grey), 0.1);
}

TEST(ImageCompare, SameFramesMatch) {
  const render::ImageDifference difference = render::compare_images(edge_frame(20, 128), edge_frame(20, 128));
  EXPECT_TRUE(difference.matches);
  EXPECT_EQ(difference.differing_pixels, 0);
  EXPECT_EQ(difference.largest_region, 0);
}

// The edge's grey changes a lot (the edge moved a fraction of a pixel): every changed pixel lies
// between a darker and a brighter flat neighbour, so it is anti-aliasing, not a difference.
TEST(ImageCompare, AnAntiAliasedEdgeThatShiftsIsForgiven) {
  const render::ImageDifference difference = render::compare_images(edge_frame(20, 60), edge_frame(20, 200));
  EXPECT_TRUE(difference.matches) << difference.summary;
  EXPECT_EQ(difference.differing_pixels, 0);
  EXPECT_EQ(difference.anti_aliased_pixels, 30);
}

// The same change inside a flat area is no edge: a line of 30 pixels differs.
TEST(ImageCompare, TheSameChangeInAFlatAreaDiffers) {
  Frame expected = plain(40, 30, 60), actual = plain(40, 30, 60);
  for (int y = 0; y < 30; ++y) set(actual, 20, y, 200, 200, 200);
  const render::ImageDifference difference = render::compare_images(expected, actual);
  EXPECT_FALSE(difference.matches);
  EXPECT_EQ(difference.differing_pixels, 30);
  EXPECT_EQ(difference.largest_region, 30);
  EXPECT_EQ(difference.left, 20);
  EXPECT_EQ(difference.right, 20);
}

// A small body recoloured in a large frame: one region of 16 pixels, 0.01 % of the frame, fails by
// the region; the same 16 pixels scattered one by one pass.
TEST(ImageCompare, ARegionFailsWhereScatteredPixelsPass) {
  const Frame expected = plain(400, 400, 200);
  Frame block = expected, scattered = expected;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      set(block, 100 + x, 50 + y, 230, 80, 0);
      set(scattered, 20 + 20 * x, 20 + 20 * y, 230, 80, 0);
    }
  const render::ImageDifference in_block = render::compare_images(expected, block);
  EXPECT_FALSE(in_block.matches) << in_block.summary;
  EXPECT_EQ(in_block.largest_region, 16);
  EXPECT_EQ(in_block.left, 100);
  EXPECT_EQ(in_block.bottom, 53);
  const render::ImageDifference apart = render::compare_images(expected, scattered);
  EXPECT_TRUE(apart.matches) << apart.summary;
  EXPECT_EQ(apart.differing_pixels, 16);
  EXPECT_EQ(apart.largest_region, 1);
}

// Diagonal neighbours join a region (8-connectivity).
TEST(ImageCompare, DiagonalPixelsAreOneRegion) {
  const Frame expected = plain(50, 50, 200);
  Frame actual = expected;
  for (int k = 0; k < 20; ++k) set(actual, 5 + k, 5 + k, 0, 0, 255);
  EXPECT_EQ(render::compare_images(expected, actual).largest_region, 20);
}

// Many small regions, none too large, still fail by their share of the frame.
TEST(ImageCompare, ManySmallRegionsFailByTheirShare) {
  const Frame expected = plain(100, 100, 200);
  Frame actual = expected;
  for (int y = 0; y < 100; y += 4)
    for (int x = 0; x < 100; x += 4) set(actual, x, y, 0, 0, 0);
  const render::ImageDifference difference = render::compare_images(expected, actual);
  EXPECT_EQ(difference.largest_region, 1);
  EXPECT_FALSE(difference.matches) << difference.summary;
}

// A sleeping body is drawn pale. Recoloured green -> vermillion, its shaded front face goes from
// (113, 135, 125) to (149, 119, 111) (as rendered), 0.09 apart: under the colour threshold, so no
// pixel differs, yet over a face of 30 x 20 pixels a person sees it, and the frames differ. The
// same change in a speck of 3 x 3 pixels does not.
TEST(ImageCompare, AFaintChangeOverAnAreaDiffers) {
  const uint8_t green[3] = {113, 135, 125}, vermillion[3] = {149, 119, 111};
  const double distance = render::colour_distance(green, vermillion);
  const render::ImageTolerance tolerance;
  ASSERT_LT(distance, tolerance.colour_threshold);
  ASSERT_GT(distance, tolerance.faint_threshold);
  auto with_patch = [](const uint8_t* colour, int size_x, int size_y) {
    Frame frame = plain(200, 150, 230);
    for (int y = 0; y < size_y; ++y)
      for (int x = 0; x < size_x; ++x) set(frame, 80 + x, 60 + y, colour[0], colour[1], colour[2]);
    return frame;
  };
  const render::ImageDifference face = render::compare_images(with_patch(green, 30, 20), with_patch(vermillion, 30, 20));
  EXPECT_FALSE(face.matches) << face.summary;
  EXPECT_EQ(face.differing_pixels, 0);
  EXPECT_EQ(face.largest_faint_region.pixels, 600);
  EXPECT_EQ(face.largest_faint_region.left, 80);
  EXPECT_EQ(face.largest_faint_region.bottom, 79);
  EXPECT_NE(face.summary.find("a faint difference over an area"), std::string::npos) << face.summary;
  const render::ImageDifference speck = render::compare_images(with_patch(green, 3, 3), with_patch(vermillion, 3, 3));
  EXPECT_TRUE(speck.matches) << speck.summary;
  EXPECT_EQ(speck.largest_faint_region.pixels, 9);
}

// A change below the faint threshold is no difference, even over an area.
TEST(ImageCompare, AFaintChangeIsNoDifference) {
  const Frame expected = plain(60, 60, 128);
  Frame actual = expected;
  for (int y = 10; y < 30; ++y)
    for (int x = 10; x < 30; ++x) set(actual, x, y, 133, 130, 126);
  EXPECT_TRUE(render::compare_images(expected, actual).matches);
}

TEST(ImageCompare, SizesThatDifferNeverMatchAndTheDiffCoversBoth) {
  const Frame expected = plain(40, 30, 128), actual = plain(50, 20, 128);
  const render::ImageDifference difference = render::compare_images(expected, actual);
  EXPECT_FALSE(difference.same_size);
  EXPECT_FALSE(difference.matches);
  EXPECT_NE(difference.summary.find("40x30 expected, 50x20 rendered"), std::string::npos) << difference.summary;
  const Frame diff = render::difference_image(expected, actual, difference);
  EXPECT_EQ(diff.width, 50);
  EXPECT_EQ(diff.height, 30);
  const Frame strip = render::side_by_side({&expected, &actual, &diff});
  EXPECT_EQ(strip.width, 8 + 40 + 8 + 50 + 8 + 50 + 8);
}

}  // namespace
}  // namespace impulse
