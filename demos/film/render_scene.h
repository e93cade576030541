// Runs a scene and films it: world -> steps -> draw list -> frame (+ overlay) -> MP4 (and PNGs).
// The world is stepped once, to the scene's end, on the calling thread before the first frame is
// drawn (the Film's constructor, scene_film.h). Then a thread of its own turns the samples into
// each frame's draw lists and overlay, a couple of frames ahead; drawing happens on the calling
// thread (llvmpipe adds its own threads); the overlay, PNG files and the encoder run on a worker
// thread, a few frames behind (frame_pipeline.h).
#pragma once
#include "demos/film/film.h"
#include "demos/scene/scene.h"
#include "physics/world.h"
#include "render/draw_list.h"
#include "render/renderer.h"
#include "render/video_encoder.h"

#include <functional>
#include <string>
#include <vector>

namespace impulse::demos {

struct RenderOptions {
  std::string video_path;        // empty: no video
  render::VideoFormat video_format = render::VideoFormat::mp4;
  std::string png_directory;     // empty: no PNG frames
  std::vector<int> png_frames;   // which frames become PNGs (numbered from 0); empty: all
  int png_spread = 0;            // > 1 (and no png_frames): that many, evenly from the first to the last
  std::vector<double> moments;   // stills at these simulated s: PNG t_0.500.png in png_directory, and `on_still`
  bool moments_at_impacts = false;  // and one at each impact that slows the video
  // Called with each still (overlaid), on the thread that finishes frames, in order of time.
  std::function<void(double time, const render::Frame& frame, const std::vector<BodyPose>& poses)> on_still;
  std::string poster_path;       // .png of a frame where something happens (SceneFilm::poster_frame), written once
                                 // the video is complete; empty: none
  std::string layout_report_path;  // .json: each video frame's overlay layout (layout_report.h), written
                                   // once the video is complete; empty: none
  // Called after each frame is drawn, with the frames finished and the frame count.
  std::function<void(int frames_done, int frame_count)> progress;
  // Called, once the video is complete, with what a viewer should know that the frames do not
  // say: panes that moved alike step for step (what differs between them changes nothing shown).
  std::function<void(const std::string& warning)> on_warning;
  render::RendererSettings renderer;
};

// What a frame shows of the world as it is, with the last step's contacts (no hold, no
// interpolation, arrow scales of 1 m per unit unless the scene sets them): for tests and stills.
render::DrawList make_draw_list(const Scene& scene, const physics::World& world, const physics::StepRecord& record);

// Renders the whole scene and returns how its [[check]]s came out. Throws on any failure; a video
// is complete under its final name or absent.
std::vector<CheckResult> render_scene(const Scene& scene, const RenderOptions& options);
// The same for two to four scenes side by side in one video (a comparison, film.h); returns each
// pane's checks.
std::vector<std::vector<CheckResult>> render_panes(const std::vector<Pane>& panes, const RenderOptions& options);

// The captions track, the chapters track and the poster written beside a video: NAME.mp4 ->
// NAME.vtt, NAME.chapters.vtt (at the impacts that slow the video, else at the captions), NAME.png.
std::string captions_path(const std::string& video_path);
std::string chapters_path(const std::string& video_path);
std::string poster_path(const std::string& video_path);

// The name a frame's PNG gets: DIRECTORY/frame_00042.png.
std::string frame_file(const std::string& directory, int64_t index);
// The name a still's PNG gets: DIRECTORY/t_0.500.png (its moment, to the millisecond).
std::string still_file(const std::string& directory, double time);

}  // namespace impulse::demos
