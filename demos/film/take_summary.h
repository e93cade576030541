// What a whole run of a world shows, known only at its end (world_take.h): it fixes the arrow
// scales, the plots' axes and the slow motion before the first frame is drawn.
#pragma once
#include <Eigen/Geometry>
#include <vector>

namespace impulse::demos {

struct TakeSummary {
  std::vector<double> impact_times;  // s: steps with a contact impulse >= slow_motion_impulse
  double largest_impulse = 0;        // N s, normal or friction, on a moving body
  double impulse_to_fit = 0;         // N s: what the automatic arrow scale fits (marks.h)
  double largest_speed = 0;          // m/s of a moving body
  std::vector<double> plot_maxima;   // one per scene.overlay.plots
  bool someone_sleeps = false;       // a moving body fell asleep at some step
  Eigen::AlignedBox3d moving_extent; // m: every moving body's bounding sphere at every step (empty: none moves)
};

}  // namespace impulse::demos
