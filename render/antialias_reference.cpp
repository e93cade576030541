#include "render/antialias_reference.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace impulse::render {
namespace {

// A fixed integer hash mapped to [0, 1): the same offsets on every machine.
float unit_hash(uint32_t i) {
  i ^= i >> 16;
  i *= 0x7feb352dU;
  i ^= i >> 15;
  i *= 0x846ca68bU;
  i ^= i >> 16;
  return float(i >> 8) / float(1 << 24);
}

}  // namespace

Frame supersampled_reference(int width, int height, RendererSettings settings, const DrawList& draw_list, int grid) {
  settings.antialiasing = Antialiasing::none;
  Renderer renderer(width, height, settings);
  std::vector<uint32_t> sums(size_t(width) * size_t(height) * 4, 0);
  for (int j = 0; j < grid; ++j) {
    for (int i = 0; i < grid; ++i) {
      const auto cell = uint32_t(j * grid + i);
      renderer.set_subpixel_offset((float(i) + unit_hash(2 * cell)) / float(grid) - 0.5f,
                                   (float(j) + unit_hash(2 * cell + 1)) / float(grid) - 0.5f);
      const Frame& frame = renderer.draw(draw_list);
      for (size_t k = 0; k < sums.size(); ++k) sums[k] += frame.rgba[k];
    }
  }
  Frame reference;
  reference.width = width;
  reference.height = height;
  reference.rgba.resize(sums.size());
  const auto count = uint32_t(grid * grid);
  for (size_t k = 0; k < sums.size(); ++k) reference.rgba[k] = uint8_t((sums[k] + count / 2) / count);
  return reference;
}

double mean_colour_error(const Frame& a, const Frame& b) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size())
    throw std::invalid_argument("mean_colour_error: the frames' sizes differ");
  uint64_t total = 0;
  for (size_t k = 0; k < a.rgba.size(); k += 4)
    for (size_t channel = 0; channel < 3; ++channel)
      total += uint64_t(std::abs(int(a.rgba[k + channel]) - int(b.rgba[k + channel])));
  const size_t values = a.rgba.size() / 4 * 3;
  return values > 0 ? double(total) / double(values) : 0.0;
}

}  // namespace impulse::render
