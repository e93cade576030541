// One rendered image as plain data: 8-bit RGBA, rows top to bottom, no padding between rows.
#pragma once
#include <cstdint>
#include <vector>

#include "render/draw_list.h"

namespace impulse::render {

struct Frame {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4 bytes; row 0 is the top of the image
};

// `frame` made width x height, every pixel `colour` (opaque, or with alpha 0 all zero).
void fill(Frame& frame, int width, int height, const Colour& colour, float alpha = 1);

// Premultiplied colour (what a transparent renderer draws and the overlay composites onto) to
// straight colour (what PNG and the encoders take): each channel divided by alpha.
void unpremultiply(Frame& frame);

// Copies `pane` into `frame` with its top-left corner at (x, y); what falls outside is cut off.
void paste(const Frame& pane, int x, int y, Frame& frame);

}  // namespace impulse::render
