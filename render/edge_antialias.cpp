#include "render/edge_antialias.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace impulse::render {
namespace {

enum Direction { kPlusX, kMinusX, kPlusY, kMinusY };
constexpr Direction kOpposite[4] = {kMinusX, kPlusX, kMinusY, kPlusY};

// Parts in units of 1/510 of a pixel: an outline stored as s (distance d = 1 - s/255) crossing this
// pixel gives the part 1/2 - d = (2s - 255)/510 beyond it; a neighbour's stored as t reaching into
// this pixel gives d - 1/2 = (255 - 2t)/510. Integers, so a pixel costs a few instructions.
constexpr int kWhole = 510;

// The part of the pixel at (x, y) to take from its neighbour in each direction (0 where there is none).
std::array<int, 4> parts_at(const uint8_t* edges, int x, int y, int width, int height) {
  const size_t index = size_t(y) * size_t(width) + size_t(x);
  const uint8_t* own = edges + 4 * index;
  const bool has[4] = {x + 1 < width, x > 0, y + 1 < height, y > 0};
  const std::ptrdiff_t step[4] = {1, -1, width, -width};
  std::array<int, 4> parts{};
  for (int direction = 0; direction < 4; ++direction) {
    if (!has[direction]) continue;
    const int mine = 2 * int(own[direction]) - 255;  // > 0: d < 1/2
    // The neighbour's outline towards this pixel, 1/2 .. 1 pixel from its centre, lies in this one.
    const uint8_t theirs = edges[4 * size_t(std::ptrdiff_t(index) + step[direction]) + size_t(kOpposite[direction])];
    const int reaching = theirs != kNoEdge ? 255 - 2 * int(theirs) : 0;  // > 0: d > 1/2
    parts[size_t(direction)] = std::max({mine, reaching, 0});
  }
  return parts;
}

// True when neither the pixels [x, x + 8) of row y nor their neighbours carry an outline
// (4 bytes a pixel: 8 pixels are 4 words of 64 bits).
bool quiet_span(const uint8_t* edges, int x, int y, int width, int height) {
  auto any = [&](int row, int first, int count) {
    const uint8_t* p = edges + 4 * (size_t(row) * size_t(width) + size_t(first));
    uint64_t bits = 0;
    for (int i = 0; i + 2 <= count; i += 2) {
      uint64_t word;
      std::memcpy(&word, p + 4 * i, sizeof word);
      bits |= word;
    }
    if (count % 2 != 0) {
      uint32_t last;
      std::memcpy(&last, p + 4 * (count - 1), sizeof last);
      bits |= last;
    }
    return bits != 0;
  };
  if (any(y, x, 8)) return false;
  if (x > 0 && any(y, x - 1, 1)) return false;
  if (x + 8 < width && any(y, x + 8, 1)) return false;
  if (y > 0 && any(y - 1, x, 8)) return false;
  return y + 1 >= height || !any(y + 1, x, 8);
}

// True when the pixel or a neighbour's side towards it has an outline (4 byte tests, no arithmetic).
bool near_outline(const uint8_t* edges, int x, int y, int width, int height) {
  const size_t index = size_t(y) * size_t(width) + size_t(x);
  uint32_t own;
  std::memcpy(&own, edges + 4 * index, sizeof own);
  return own != 0 || (x + 1 < width && edges[4 * (index + 1) + kMinusX] != kNoEdge) ||
         (x > 0 && edges[4 * (index - 1) + kPlusX] != kNoEdge) ||
         (y + 1 < height && edges[4 * (index + size_t(width)) + kMinusY] != kNoEdge) ||
         (y > 0 && edges[4 * (index - size_t(width)) + kPlusY] != kNoEdge);
}

}  // namespace

void resolve_edges(const uint8_t* colour, const uint8_t* edges, int width, int height, Frame& frame) {
  frame.width = width;
  frame.height = height;
  frame.rgba.resize(size_t(width) * size_t(height) * 4);
  const size_t row_bytes = size_t(width) * 4;
  const std::ptrdiff_t step[4] = {4, -4, 4 * std::ptrdiff_t(width), -4 * std::ptrdiff_t(width)};
  for (int y = 0; y < height; ++y) {
    // GL's first row is the bottom one; Frame's is the top one.
    uint8_t* out = frame.rgba.data() + size_t(height - 1 - y) * row_bytes;
    const uint8_t* in = colour + size_t(y) * row_bytes;
    std::memcpy(out, in, row_bytes);
    for (int x = 0; x < width; ++x) {
      if (x % 8 == 0 && x + 8 <= width && quiet_span(edges, x, y, width, height)) {
        x += 7;
        continue;
      }
      if (!near_outline(edges, x, y, width, height)) continue;
      std::array<int, 4> parts = parts_at(edges, x, y, width, height);
      int taken = parts[0] + parts[1] + parts[2] + parts[3];
      if (taken <= 0) continue;
      // Outlines across x and across y (a corner): the part beyond both is in each strip, so the
      // pixel takes x + y - x*y in all (exact for a right-angled corner), shared in proportion.
      const int across_x = parts[kPlusX] + parts[kMinusX], across_y = parts[kPlusY] + parts[kMinusY];
      if (across_x > 0 && across_y > 0) {
        const int beyond = across_x + across_y - across_x * across_y / kWhole;
        for (int& part : parts) part = part * beyond / taken;
        taken = parts[0] + parts[1] + parts[2] + parts[3];
      }
      if (taken > kWhole) {  // outlines closer than a pixel: shared out
        for (int& part : parts) part = part * kWhole / taken;
        taken = parts[0] + parts[1] + parts[2] + parts[3];
      }
      const uint8_t* self = in + 4 * size_t(x);
      int mixed[3] = {self[0] * (kWhole - taken), self[1] * (kWhole - taken), self[2] * (kWhole - taken)};
      for (int direction = 0; direction < 4; ++direction) {
        const int part = parts[size_t(direction)];
        if (part == 0) continue;  // also where there is no neighbour
        const uint8_t* other = self + step[direction];
        for (int channel = 0; channel < 3; ++channel) mixed[channel] += part * other[channel];
      }
      for (int channel = 0; channel < 3; ++channel)
        out[4 * size_t(x) + size_t(channel)] = uint8_t((mixed[channel] + kWhole / 2) / kWhole);
    }
  }
}

}  // namespace impulse::render
