// Two frames compared as three.js's and Blender's render tests compare them: a pixel differs when
// one of its channels is more than `pixel_threshold` (0..255) away, and the frames match while at
// most `max_differing_share` of the pixels differ. The project's golden tests and `impulse verify`
// both use it.
#pragma once
#include <string>

#include "render/frame.h"

namespace impulse::render {

struct ImageTolerance {
  int pixel_threshold = 24;
  double max_differing_share = 0.005;  // 0.5 %
};

struct ImageDifference {
  bool same_size = false;
  bool matches = false;
  double differing_share = 0;          // of the pixels
  int left = 0, top = 0, right = -1, bottom = -1;  // the box around the differing pixels (pixels)
  std::string summary;                 // "1.20 % of the pixels differ by more than 24 (allowed: 0.50 %), in x 10..90, y 40..70"
};

ImageDifference compare_images(const Frame& expected, const Frame& actual, ImageTolerance tolerance = {});

// `expected` faded towards white, with the pixels that differ from `actual` in red.
Frame difference_image(const Frame& expected, const Frame& actual, int pixel_threshold);

}  // namespace impulse::render
