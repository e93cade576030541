// A drawn frame as GL gives it back, before its last step on the CPU: rows bottom to top, and with
// edge anti-aliasing each pixel's nearest outlines (edge_antialias.h). Finishing it — turning the
// rows top to bottom and, with edges, mixing each pixel an outline crosses — needs no GL, so a
// pipeline can do it on another thread while the next frame draws (demos/film/frame_pipeline.h).
#pragma once
#include <cstdint>
#include <vector>

#include "render/frame.h"

namespace impulse::render {

struct ReadBack {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> bottom_up_rgba;   // width * height * 4 bytes; row 0 is the bottom of the image
  std::vector<uint8_t> bottom_up_edges;  // the same size with edge anti-aliasing, else empty
};

// `frame` gets the finished image (resized as needed).
void finish(const ReadBack& read_back, Frame& frame);

}  // namespace impulse::render
