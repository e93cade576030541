// Runs a scene and films it: world -> steps -> draw list -> frame -> MP4 (and PNGs).
#pragma once
#include "demos/scene_file.h"
#include "physics/world.h"
#include "render/draw_list.h"

#include <string>

namespace impulse::demos {

struct RenderOptions {
  std::string video_path;        // .mp4; empty: no video
  std::string png_directory;     // empty: no PNG frames
  bool progress = false;         // a progress line on stderr
};

physics::World build_world(const Scene& scene);

// What frame shows the world, from the bodies and the last step's records.
render::DrawList make_draw_list(const Scene& scene, const physics::World& world, const physics::StepRecord& record);

// Renders the whole scene. Throws on any failure; a video is complete under its final name or
// absent.
void render_scene(const Scene& scene, const RenderOptions& options);

}  // namespace impulse::demos
