// One rendered image as plain data: 8-bit RGBA, rows top to bottom, no padding between rows.
#pragma once
#include <cstdint>
#include <vector>

namespace impulse::render {

struct Frame {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4 bytes; row 0 is the top of the image
};

}  // namespace impulse::render
