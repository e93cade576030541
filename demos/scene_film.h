// What each frame of a scene shows, frame after frame: the world stepped to the frame's moment
// (its own fixed step; bodies interpolated between steps), the playback timeline, held contacts,
// plots, camera motion, and the overlay. Produces plain data (a DrawList and an Overlay per
// frame), so it can run on a thread of its own ahead of drawing.
#pragma once
#include "demos/camera_path.h"
#include "demos/contact_hold.h"
#include "demos/frame_overlay.h"
#include "demos/marks.h"
#include "demos/playback_timeline.h"
#include "demos/plot_recorder.h"
#include "demos/scene_draw_list.h"
#include "demos/scene_file.h"
#include "demos/scene_preview.h"
#include "physics/world.h"
#include "render/draw_list.h"
#include "render/overlay.h"

#include <vector>

namespace impulse::demos {

struct ScenePicture {
  render::DrawList draw_list;
  render::Overlay overlay;
};

class SceneFilm {
 public:
  // Runs the scene's preview (scene_preview.h) first. `scene` must outlive the film.
  SceneFilm(const Scene& scene, int width, int height);

  int frame_count() const { return timeline_.frame_count(); }
  int next_frame() const { return frame_; }
  // Fills `picture` with the next frame (from 0 up to frame_count() - 1).
  void next(ScenePicture& picture);

 private:
  const Scene& scene_;
  int fps_;
  ScenePreview preview_;
  ArrowScales scales_;
  PlaybackTimeline timeline_;
  physics::World world_;
  PlotRecorder plots_;
  ContactHold hold_;
  CameraPath camera_path_;
  FrameOverlay overlay_maker_;
  std::vector<BodyPose> before_, after_, shown_;
  double time_ = 0;  // simulated s of the next frame
  int frame_ = 0;
};

}  // namespace impulse::demos
