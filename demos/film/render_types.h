// The scene's plain settings as the renderer and the encoder take them.
#pragma once
#include "demos/scene/scene.h"
#include "render/draw_list.h"
#include "render/video_encoder.h"

namespace impulse::demos {

inline render::Colour to_render(const Colour& colour) { return {colour.r, colour.g, colour.b}; }

inline render::Camera to_render(const CameraSetting& camera) {
  return {camera.position, camera.target, camera.fov_y_degrees};
}

inline render::VideoSettings to_render(const VideoSetting& video) {
  render::VideoSettings settings;
  settings.width = video.width;
  settings.height = video.height;
  settings.fps = video.fps;
  settings.crf = video.crf;
  settings.preset = video.preset;
  return settings;
}

}  // namespace impulse::demos
