#include "render/read_back.h"

#include <cstring>

#include "render/edge_antialias.h"

namespace impulse::render {

void finish(const ReadBack& read_back, Frame& frame) {
  const int width = read_back.width, height = read_back.height;
  if (!read_back.bottom_up_edges.empty()) {
    resolve_edges(read_back.bottom_up_rgba.data(), read_back.bottom_up_edges.data(), width, height, frame);
    return;
  }
  // GL's first row is the bottom one; Frame's is the top one.
  frame.width = width;
  frame.height = height;
  frame.rgba.resize(read_back.bottom_up_rgba.size());
  const size_t row_bytes = static_cast<size_t>(width) * 4;
  for (int row = 0; row < height; ++row) {
    std::memcpy(frame.rgba.data() + static_cast<size_t>(row) * row_bytes,
                read_back.bottom_up_rgba.data() + static_cast<size_t>(height - 1 - row) * row_bytes, row_bytes);
  }
}

}  // namespace impulse::render
