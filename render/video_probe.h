// What a video file holds, read back from its container (libavformat): for the gallery, which
// states each video's size and length as they were rendered.
#pragma once
#include <string>

namespace impulse::render {

struct VideoFacts {
  int width = 0;
  int height = 0;
  double duration = 0;  // s
  std::string comment;  // the container's comment tag (the --set settings)
};

// Throws std::runtime_error naming the file when it cannot be read as a video.
VideoFacts probe_video(const std::string& path);

}  // namespace impulse::render
