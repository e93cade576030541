// The 2D overlay of one frame of a scene: title, legend, captions, the clock and playback speed,
// a label with the value beside the chosen arrow, and the live plots.
#pragma once
#include "demos/marks.h"
#include "demos/plot_recorder.h"
#include "demos/scene_draw_list.h"
#include "demos/scene_file.h"
#include "demos/scene_preview.h"
#include "render/camera_view.h"
#include "render/overlay.h"

#include <string>
#include <vector>

namespace impulse::demos {

struct FrameState {
  double time = 0;            // simulated s shown
  double speed = 1;           // playback factor at that moment
  bool slow_motion = false;   // slowed for an impact
  const std::vector<physics::Body>* bodies = nullptr;
  const std::vector<BodyPose>* poses = nullptr;
  const std::vector<physics::ContactRecord>* contacts = nullptr;
  render::Camera camera;
};

class FrameOverlay {
 public:
  FrameOverlay(const Scene& scene, const ScenePreview& preview, const ArrowScales& scales, int width, int height);

  // Fills `overlay` (reusing its memory) for the frame.
  void make(const FrameState& state, const PlotRecorder& plots, render::Overlay& overlay) const;

 private:
  void add_label(const FrameState& state, const render::CameraView& view, render::Overlay& overlay) const;

  const Scene& scene_;
  const ScenePreview& preview_;
  ArrowScales scales_;
  int width_;
  int height_;
  int label_body_ = -1;   // -1: the largest anywhere
  std::string plot_body_name_;
};

}  // namespace impulse::demos
