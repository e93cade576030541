#include "render/edge_antialias.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace impulse::render {
namespace {

enum Direction { kPlusX, kMinusX, kPlusY, kMinusY };

// Parts in units of 1/510 of a pixel: an outline stored as s (distance d = 1 - s/255) crossing this
// pixel gives the part 1/2 - d = (2s - 255)/510 beyond it; a neighbour's stored as t reaching into
// this pixel gives d - 1/2 = (255 - 2t)/510. Integers, so a pixel costs a few instructions.
constexpr int kWhole = 510;

// The part of a pixel beyond its own outline stored as `mine`, or beyond its neighbour's outline
// towards it stored as `theirs`, whichever is larger (0: none).
inline int part_of(uint8_t mine, uint8_t theirs) {
  const int own = 2 * int(mine) - 255;                       // > 0: d < 1/2
  const int reaching = theirs != kNoEdge ? 255 - 2 * int(theirs) : 0;  // > 0: d > 1/2
  return std::max({own, reaching, 0});
}

// The parts of the pixel at (x, y) to take from its neighbour in each direction (0 where there is none).
std::array<int, 4> parts_at(const uint8_t* edges, int x, int y, int width, int height) {
  const uint8_t* own = edges + 4 * (size_t(y) * size_t(width) + size_t(x));
  const std::ptrdiff_t row = 4 * std::ptrdiff_t(width);
  std::array<int, 4> parts{};
  if (x + 1 < width) parts[kPlusX] = part_of(own[kPlusX], own[4 + kMinusX]);
  if (x > 0) parts[kMinusX] = part_of(own[kMinusX], own[-4 + kPlusX]);
  if (y + 1 < height) parts[kPlusY] = part_of(own[kPlusY], own[row + kMinusY]);
  if (y > 0) parts[kMinusY] = part_of(own[kMinusY], own[-row + kPlusY]);
  return parts;
}

// The pixel's colour mixed with its neighbours' by `parts` (0 towards a side with no neighbour, whose
// pointer is then the pixel's own).
void mix(std::array<int, 4> parts, const uint8_t* self, const uint8_t* right, const uint8_t* left, const uint8_t* up,
         const uint8_t* down, uint8_t* out) {
  int taken = parts[0] + parts[1] + parts[2] + parts[3];
  if (taken <= 0) return;
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
  const int keep = kWhole - taken;
  for (int channel = 0; channel < 4; ++channel) {  // alpha too: a transparent frame's outline takes in its coverage
    const int mixed = self[channel] * keep + parts[kPlusX] * right[channel] + parts[kMinusX] * left[channel] +
                      parts[kPlusY] * up[channel] + parts[kMinusY] * down[channel];
    out[channel] = uint8_t((mixed + kWhole / 2) / kWhole);
  }
}

// Bit x of word x / 64 set where pixel x of the row has an outline byte (4 bytes a pixel).
void outline_mask(const uint8_t* row, int width, uint64_t* mask) {
  for (int first = 0; first < width; first += 64) {
    uint64_t bits = 0;
    const int count = std::min(64, width - first);
    int i = 0;
#ifdef __SSE2__
    // Four pixels at a time: a 32-bit lane equal to zero has no outline.
    const __m128i zero = _mm_setzero_si128();
    for (; i + 4 <= count; i += 4) {
      const __m128i pixels = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 4 * size_t(first + i)));
      const int none = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(pixels, zero)));
      bits |= uint64_t(~none & 0xF) << i;
    }
#endif
    for (; i < count; ++i) {
      uint32_t word;
      std::memcpy(&word, row + 4 * size_t(first + i), sizeof word);
      bits |= uint64_t(word != 0) << i;
    }
    mask[first / 64] = bits;
  }
}

}  // namespace

void resolve_edges(const uint8_t* colour, const uint8_t* edges, int width, int height, Frame& frame) {
  frame.width = width;
  frame.height = height;
  frame.rgba.resize(size_t(width) * size_t(height) * 4);
  const size_t row_bytes = size_t(width) * 4;
  // Three rows' outline masks, cycled: the rows below, at and above the one resolved.
  const int words = (width + 63) / 64;
  std::vector<uint64_t> masks(3 * size_t(words), 0);
  auto mask_of = [&](int y) { return masks.data() + size_t(y % 3) * size_t(words); };
  if (height > 0) outline_mask(edges, width, mask_of(0));
  for (int y = 0; y < height; ++y) {
    // GL's first row is the bottom one; Frame's is the top one.
    uint8_t* out = frame.rgba.data() + size_t(height - 1 - y) * row_bytes;
    const uint8_t* in = colour + size_t(y) * row_bytes;
    std::memcpy(out, in, row_bytes);
    if (y + 1 < height) outline_mask(edges + size_t(y + 1) * row_bytes, width, mask_of(y + 1));
    // A pixel takes in only from outlines on itself or on its four neighbours' sides towards it.
    const uint64_t* below = y > 0 ? mask_of(y - 1) : nullptr;
    const uint64_t* at = mask_of(y);
    const uint64_t* above = y + 1 < height ? mask_of(y + 1) : nullptr;
    for (int word = 0; word < words; ++word) {
      const uint64_t left_carry = word > 0 ? at[word - 1] >> 63 : 0;
      const uint64_t right_carry = word + 1 < words ? at[word + 1] << 63 : 0;
      uint64_t near_bits = at[word] | (at[word] << 1) | left_carry | (at[word] >> 1) | right_carry;
      if (below) near_bits |= below[word];
      if (above) near_bits |= above[word];
      while (near_bits != 0) {
        const int x = 64 * word + std::countr_zero(near_bits);
        near_bits &= near_bits - 1;
        if (x >= width) break;
        const uint8_t* self = in + 4 * size_t(x);
        mix(parts_at(edges, x, y, width, height), self, x + 1 < width ? self + 4 : self, x > 0 ? self - 4 : self,
            y + 1 < height ? self + row_bytes : self, y > 0 ? self - row_bytes : self, out + 4 * size_t(x));
      }
    }
  }
}

}  // namespace impulse::render
