#include "demos/scene/video_quality.h"

namespace impulse::demos {

std::optional<VideoSetting> quality_preset(std::string_view name) {
  VideoSetting video;
  if (name == "low") {
    video.width = 854;
    video.height = 480;
    video.fps = 15;
    video.crf = 23;
  } else if (name == "medium") {
    video.width = 1280;
    video.height = 720;
    video.fps = 30;
    video.crf = 20;
  } else if (name == "high") {
    video.width = 1920;
    video.height = 1080;
    video.fps = 60;
    video.crf = 18;
  } else {
    return std::nullopt;
  }
  return video;
}

}  // namespace impulse::demos
