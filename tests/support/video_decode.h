// Decodes a whole video file (MP4, WebM with its alpha, GIF) back into RGBA frames, for tests of
// the encoder and the demos.
#pragma once
#include <string>
#include <vector>

#include "render/frame.h"

namespace impulse::testing {

struct DecodedVideo {
  int width = 0;
  int height = 0;
  double fps = 0.0;  // the stream's average frame rate
  std::string comment;  // the file's comment tag
  std::vector<render::Frame> frames;  // every frame in presentation order, RGBA, rows top to bottom
};

// Throws std::runtime_error naming the file if it cannot be opened or decoded.
DecodedVideo decode_video(const std::string& path);

}  // namespace impulse::testing
