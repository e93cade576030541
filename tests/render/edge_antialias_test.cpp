// The edge anti-aliasing pass on made-up images: a straight outline at a known place must give
// each pixel it crosses its true coverage, from either side, along x and along y.
#include "render/edge_antialias.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impulse {
namespace {

constexpr int kWidth = 8;
constexpr int kHeight = 6;

uint8_t stored(float distance) { return uint8_t(std::lround((1.0f - distance) * 255.0f)); }
enum { kPlusX, kMinusX, kPlusY, kMinusY };

// Black where the object is (x < edge, or y < edge, bottom-up), white elsewhere (no outline:
// the background); the object's pixels carry their offset to its outline as the shaders write it.
struct Image {
  std::vector<uint8_t> colour = std::vector<uint8_t>(kWidth * kHeight * 4, 255);
  std::vector<uint8_t> edges = std::vector<uint8_t>(kWidth * kHeight * 4, render::kNoEdge);
};

Image outline_across_x(float edge) {
  Image image;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float centre = float(x) + 0.5f;
      if (centre >= edge) continue;
      const size_t i = size_t(y * kWidth + x);
      for (int c = 0; c < 3; ++c) image.colour[4 * i + size_t(c)] = 0;
      if (edge - centre < 1.0f) image.edges[4 * i + kPlusX] = stored(edge - centre);
    }
  }
  return image;
}

Image outline_across_y(float edge) {
  Image image;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float centre = float(y) + 0.5f;
      if (centre >= edge) continue;
      const size_t i = size_t(y * kWidth + x);
      for (int c = 0; c < 3; ++c) image.colour[4 * i + size_t(c)] = 0;
      if (edge - centre < 1.0f) image.edges[4 * i + kPlusY] = stored(edge - centre);
    }
  }
  return image;
}

// The value a pixel of the white background keeps where the object covers `covered` of it.
int expected(float covered) { return int(std::lround(255.0f * (1.0f - covered))); }

TEST(EdgeAntialias, AnOutlineCrossingTheObjectsPixelMixesInTheBackground) {
  const Image image = outline_across_x(2.8f);  // pixel 2 (centre 2.5) is 0.8 covered
  render::Frame frame;
  render::resolve_edges(image.colour.data(), image.edges.data(), kWidth, kHeight, frame);
  for (int row = 0; row < kHeight; ++row) {
    const uint8_t* line = frame.rgba.data() + size_t(row * kWidth * 4);
    EXPECT_EQ(line[4 * 1], 0);
    EXPECT_NEAR(line[4 * 2], expected(0.8f), 1);
    EXPECT_EQ(line[4 * 3], 255);
    EXPECT_EQ(line[4 * 2 + 3], 255) << "alpha stays opaque";
  }
}

TEST(EdgeAntialias, AnOutlineReachingIntoTheBackgroundsPixelMixesInTheObject) {
  const Image image = outline_across_x(3.3f);  // pixel 3 (centre 3.5) is 0.3 covered
  render::Frame frame;
  render::resolve_edges(image.colour.data(), image.edges.data(), kWidth, kHeight, frame);
  for (int row = 0; row < kHeight; ++row) {
    const uint8_t* line = frame.rgba.data() + size_t(row * kWidth * 4);
    EXPECT_EQ(line[4 * 2], 0);
    EXPECT_NEAR(line[4 * 3], expected(0.3f), 1);
    EXPECT_EQ(line[4 * 4], 255);
  }
}

TEST(EdgeAntialias, AlongYAndWithRowsTurnedTopToBottom) {
  for (const float edge : {1.3f, 1.8f, 2.05f, 2.45f}) {
    const Image image = outline_across_y(edge);
    render::Frame frame;
    render::resolve_edges(image.colour.data(), image.edges.data(), kWidth, kHeight, frame);
    ASSERT_EQ(frame.width, kWidth);
    ASSERT_EQ(frame.height, kHeight);
    for (int y = 0; y < kHeight; ++y) {  // bottom-up, as the object's outline was given
      const float covered = std::clamp(edge - float(y), 0.0f, 1.0f);
      const int row = kHeight - 1 - y;
      for (int x = 0; x < kWidth; ++x)
        EXPECT_NEAR(frame.rgba[size_t((row * kWidth + x) * 4 + 1)], expected(covered), 1) << "edge " << edge << ", y " << y;
    }
  }
}

TEST(EdgeAntialias, APartThinnerThanAPixelTakesInBothSides) {
  Image image;  // a black line from x = 2.2 to 2.8: pixel 2 is 0.6 covered, its outlines 0.3 either side
  for (int y = 0; y < kHeight; ++y) {
    const size_t i = size_t(y * kWidth + 2);
    for (int c = 0; c < 3; ++c) image.colour[4 * i + size_t(c)] = 0;
    image.edges[4 * i + kPlusX] = stored(0.3f);
    image.edges[4 * i + kMinusX] = stored(0.3f);
  }
  render::Frame frame;
  render::resolve_edges(image.colour.data(), image.edges.data(), kWidth, kHeight, frame);
  for (int row = 0; row < kHeight; ++row) {
    const uint8_t* line = frame.rgba.data() + size_t(row * kWidth * 4);
    EXPECT_EQ(line[4 * 1], 255);
    EXPECT_NEAR(line[4 * 2], expected(0.6f), 1);
    EXPECT_EQ(line[4 * 3], 255);
  }
}

TEST(EdgeAntialias, ACornersPartBeyondBothOutlinesIsTakenOnce) {
  Image image;  // a black square up to x = 3.8 and y = 2.8: pixel (3, 2) is 0.8 x 0.8 covered
  for (int y = 0; y <= 2; ++y) {
    for (int x = 0; x <= 3; ++x) {
      const size_t i = size_t(y * kWidth + x);
      for (int c = 0; c < 3; ++c) image.colour[4 * i + size_t(c)] = 0;
      if (x == 3) image.edges[4 * i + kPlusX] = stored(0.3f);
      if (y == 2) image.edges[4 * i + kPlusY] = stored(0.3f);
    }
  }
  render::Frame frame;
  render::resolve_edges(image.colour.data(), image.edges.data(), kWidth, kHeight, frame);
  auto at = [&](int x, int y) { return int(frame.rgba[size_t(((kHeight - 1 - y) * kWidth + x) * 4)]); };
  EXPECT_NEAR(at(3, 2), expected(0.8f * 0.8f), 1);
  EXPECT_NEAR(at(3, 1), expected(0.8f), 1);
  EXPECT_NEAR(at(2, 2), expected(0.8f), 1);
  EXPECT_EQ(at(2, 1), 0);
}

TEST(EdgeAntialias, WithoutOutlinesTheImageIsOnlyTurned) {
  Image image;
  for (size_t i = 0; i < image.colour.size(); ++i) image.colour[i] = uint8_t(i * 7);
  render::Frame frame;
  render::resolve_edges(image.colour.data(), image.edges.data(), kWidth, kHeight, frame);
  for (int y = 0; y < kHeight; ++y)
    for (int k = 0; k < kWidth * 4; ++k)
      EXPECT_EQ(frame.rgba[size_t((kHeight - 1 - y) * kWidth * 4 + k)], image.colour[size_t(y * kWidth * 4 + k)]);
}

}  // namespace
}  // namespace impulse
