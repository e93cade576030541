// The series behind the overlay's live plots: kinetic energy (J), the magnitude of the total
// linear momentum (kg m/s) and one body's speed (m/s), one sample per physics step. A plot shows
// the samples up to its frame's step; past kMaxPoints it shows every 2nd, then every 4th, ...
// sample, so a long video keeps plots of a few hundred to 2048 points. Maxima count every step.
#pragma once
#include "demos/scene/view_options.h"
#include "physics/world.h"
#include "render/overlay.h"

#include <cstdint>
#include <vector>

namespace impulse::demos {

// The body a "speed" plot follows: `name` if given, else the first body that can move (-1: none).
int plotted_body(const std::vector<physics::Body>& bodies, const std::string& name);

class PlotRecorder {
 public:
  // Maxima and the plots' points from simulated time `from` on.
  PlotRecorder(std::vector<PlotKind> kinds, int body, double from = 0);
  void add_step(const physics::StepRecord& record, const std::vector<physics::Body>& bodies);
  int64_t steps() const { return steps_; }
  // The plots of the first `steps` samples, with fixed value ranges when `maxima` (one per kind)
  // are given.
  std::vector<render::Plot> plots(int64_t steps, double duration, const std::vector<double>& maxima,
                                  const std::string& body_name) const;
  // Largest value of each kind, in the order of the kinds.
  std::vector<double> maxima() const { return maxima_; }

 private:
  static constexpr size_t kMaxPoints = 2048;

  std::vector<PlotKind> kinds_;
  int body_;
  double from_;
  std::vector<std::vector<render::Vec2f>> samples_;  // one per kind, one per step
  std::vector<double> maxima_;                       // one per kind
  int64_t steps_ = 0;
};

}  // namespace impulse::demos
