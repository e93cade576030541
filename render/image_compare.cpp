#include "render/image_compare.h"

#include <cstdio>
#include <cstdlib>

namespace impulse::render {
namespace {

bool differs(const Frame& a, const Frame& b, size_t i, int threshold) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > threshold) return true;
  return false;
}

}  // namespace

ImageDifference compare_images(const Frame& expected, const Frame& actual, ImageTolerance tolerance) {
  ImageDifference difference;
  difference.same_size = expected.width == actual.width && expected.height == actual.height &&
                         expected.rgba.size() == actual.rgba.size();
  if (!difference.same_size) {
    difference.summary = "the sizes differ: " + std::to_string(expected.width) + "x" + std::to_string(expected.height) +
                         " expected, " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " rendered";
    return difference;
  }
  size_t count = 0;
  difference.left = expected.width;
  difference.top = expected.height;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x) {
      if (!differs(expected, actual, (size_t(y) * expected.width + x) * 4, tolerance.pixel_threshold)) continue;
      ++count;
      difference.left = std::min(difference.left, x);
      difference.right = std::max(difference.right, x);
      difference.top = std::min(difference.top, y);
      difference.bottom = std::max(difference.bottom, y);
    }
  difference.differing_share = double(count) / double(size_t(expected.width) * expected.height);
  difference.matches = difference.differing_share <= tolerance.max_differing_share;
  char text[200];
  if (count == 0) {
    std::snprintf(text, sizeof text, "no pixel differs by more than %d", tolerance.pixel_threshold);
  } else {
    std::snprintf(text, sizeof text, "%.2f %% of the pixels differ by more than %d (allowed: %.2f %%), in x %d..%d, y %d..%d",
                  100 * difference.differing_share, tolerance.pixel_threshold, 100 * tolerance.max_differing_share,
                  difference.left, difference.right, difference.top, difference.bottom);
  }
  difference.summary = text;
  return difference;
}

Frame difference_image(const Frame& expected, const Frame& actual, int pixel_threshold) {
  Frame diff = expected;
  for (size_t i = 0; i < diff.rgba.size(); i += 4) {
    const bool red = differs(expected, actual, i, pixel_threshold);
    for (int c = 0; c < 3; ++c) diff.rgba[i + c] = red ? (c == 0 ? 255 : 0) : uint8_t(191 + expected.rgba[i + c] / 4);
    diff.rgba[i + 3] = 255;
  }
  return diff;
}

}  // namespace impulse::render
