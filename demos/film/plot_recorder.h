// The series behind the overlay's live plots: kinetic energy (J), the magnitude of the total
// linear momentum (kg m/s) and the speed of one body or several (m/s), one sample per physics step. A plot shows
// the samples up to its frame's step; past kMaxPoints it shows every 2nd, then every 4th, ...
// sample, so a long video keeps plots of a few hundred to 2048 points. Maxima count every step.
#pragma once
#include "demos/scene/view_options.h"
#include "physics/world.h"
#include "render/overlay.h"

#include <cstdint>
#include <vector>

namespace impulse::demos {

// The bodies a "speed" plot follows: those named, else the first body that can move (none: empty).
std::vector<int> plotted_bodies(const std::vector<physics::Body>& bodies, const std::vector<std::string>& names);

// A "speed" curve's body: its name, and its colour where the plot has several.
struct PlotCurve {
  std::string name;
  render::Colour colour;
};

class PlotRecorder {
 public:
  // Maxima and the plots' points from simulated time `from` on.
  PlotRecorder(std::vector<PlotKind> kinds, std::vector<int> bodies, double from = 0);
  void add_step(const physics::StepRecord& record, const std::vector<physics::Body>& bodies);
  int64_t steps() const { return steps_; }
  // The plots of the first `steps` samples, with fixed value ranges when `maxima` (one per kind)
  // are given; `curves`, the speed plot's bodies (plotted_bodies' order).
  std::vector<render::Plot> plots(int64_t steps, double duration, const std::vector<double>& maxima,
                                  const std::vector<PlotCurve>& curves) const;
  // Largest value of each kind, in the order of the kinds.
  std::vector<double> maxima() const { return maxima_; }

 private:
  static constexpr size_t kMaxPoints = 2048;

  std::vector<PlotKind> kinds_;
  std::vector<int> bodies_;
  double from_;
  std::vector<std::vector<std::vector<render::Vec2f>>> samples_;  // per kind, per curve (a speed's per body), per step
  std::vector<double> maxima_;                       // one per kind
  int64_t steps_ = 0;
};

}  // namespace impulse::demos
