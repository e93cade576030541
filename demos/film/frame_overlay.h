// The 2D overlay of one frame of a scene: title, legend, captions, the clock and playback speed,
// a label with the value beside the chosen arrow, the live plots, and the typeset equations.
#pragma once
#include "demos/film/impact_numbers.h"
#include "demos/film/live_equations.h"
#include "demos/film/marks.h"
#include "demos/film/plot_recorder.h"
#include "demos/film/scene_draw_list.h"
#include "demos/scene/scene.h"
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
  int64_t plotted_steps = 0;  // steps the plots show
  const ImpactNumbers* impact = nullptr;  // the latest impact, for the equations on screen
  const std::vector<render::ArrowItem>* arrows = nullptr;  // drawn under the overlay: labels avoid them
  render::Camera camera;
};

class FrameOverlay {
 public:
  FrameOverlay(const Scene& scene, TakeSummary summary, const ArrowScales& scales, int width, int height);

  // Typesets every equation the frames will show with these impacts (the samples'), before any
  // frame is drawn: LiveEquations::prepare.
  void prepare(const std::vector<const ImpactNumbers*>& impacts) const { equations_.prepare(impacts); }
  // Where the moving bodies go over the whole film (BodyPaths), given to every frame's overlay.
  void set_body_paths(std::vector<render::ScreenBox> paths) { body_paths_ = std::move(paths); }
  // Fills `overlay` (reusing its memory) for the frame.
  void make(const FrameState& state, const PlotRecorder& plots, render::Overlay& overlay) const;

 private:
  void add_label(const FrameState& state, const render::CameraView& view, render::Overlay& overlay) const;

  const Scene& scene_;
  TakeSummary summary_;
  ArrowScales scales_;
  int width_;
  int height_;
  int label_body_ = -1;   // -1: the largest anywhere
  LiveEquations equations_;
  std::string plot_body_name_;
  std::vector<render::ScreenBox> body_paths_;
};

}  // namespace impulse::demos
