#include "render/frame.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace impulse::render {

void fill(Frame& frame, int width, int height, const Colour& colour, float alpha) {
  frame.width = width;
  frame.height = height;
  frame.rgba.resize(size_t(width) * height * 4);
  auto byte = [&](float channel) { return uint8_t(std::lround(std::clamp(channel * alpha, 0.0f, 1.0f) * 255)); };
  const uint8_t pixel[4] = {byte(colour.r), byte(colour.g), byte(colour.b), byte(1.0f)};
  for (size_t i = 0; i < frame.rgba.size(); i += 4) std::memcpy(&frame.rgba[i], pixel, 4);
}

void unpremultiply(Frame& frame) {
  for (size_t i = 0; i < frame.rgba.size(); i += 4) {
    uint8_t* p = &frame.rgba[i];
    const unsigned alpha = p[3];
    if (alpha == 255) continue;
    for (int c = 0; c < 3; ++c) p[c] = alpha == 0 ? 0 : uint8_t(std::min(255u, (p[c] * 255u + alpha / 2) / alpha));
  }
}

void paste(const Frame& pane, int x, int y, Frame& frame) {
  const int left = std::max(x, 0), right = std::min(x + pane.width, frame.width);
  if (right <= left) return;
  for (int row = std::max(y, 0); row < std::min(y + pane.height, frame.height); ++row) {
    const uint8_t* from = pane.rgba.data() + (size_t(row - y) * pane.width + (left - x)) * 4;
    std::memcpy(frame.rgba.data() + (size_t(row) * frame.width + left) * 4, from, size_t(right - left) * 4);
  }
}

}  // namespace impulse::render
