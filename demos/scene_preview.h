// A first run of the whole simulation, before any frame is drawn, to learn what the video must
// be ready for: when the impacts come (slow motion starts before them), and the largest impulse,
// speed and plotted values (arrow scales and plot axes that stay fixed while the video plays).
// The world is deterministic, so the filmed run repeats it exactly.
#pragma once
#include "demos/scene_file.h"

#include <vector>

namespace impulse::demos {

struct ScenePreview {
  std::vector<double> impact_times;  // s: steps with a contact impulse >= slow_motion_impulse
  double largest_impulse = 0;        // N s, normal or friction, on a moving body
  double largest_speed = 0;          // m/s of a moving body
  std::vector<double> plot_maxima;   // one per scene.overlay.plots
};

// Runs the preview only when the scene needs it (slow motion, an automatic arrow scale for marks
// it draws, or plots); else returns an empty preview. For heavy scenes the preview doubles the
// physics' cost.
ScenePreview preview_scene(const Scene& scene);

}  // namespace impulse::demos
