// The series behind the overlay's live plots: kinetic energy (J), the magnitude of the total
// linear momentum (kg m/s) and one body's speed (m/s). One sample per physics step until a
// series holds kMaxPoints; then every other one is dropped and sampling halves, so a long video
// keeps the same memory (a plot is a few hundred pixels wide anyway). Maxima count every step.
#pragma once
#include "demos/view_options.h"
#include "physics/world.h"
#include "render/overlay.h"

#include <cstdint>
#include <vector>

namespace impulse::demos {

// The body a "speed" plot follows: `name` if given, else the first body that can move (-1: none).
int plotted_body(const std::vector<physics::Body>& bodies, const std::string& name);

class PlotRecorder {
 public:
  PlotRecorder(std::vector<PlotKind> kinds, int body);
  void add_step(const physics::StepRecord& record, const std::vector<physics::Body>& bodies);
  // The plots up to now, with fixed value ranges when `maxima` (one per kind) are given.
  std::vector<render::Plot> plots(double duration, const std::vector<double>& maxima, const std::string& body_name) const;
  // Largest value of each kind so far, in the order of the kinds.
  std::vector<double> maxima() const;

 private:
  static constexpr size_t kMaxPoints = 2048;

  std::vector<PlotKind> kinds_;
  int body_;
  std::vector<std::vector<render::Vec2f>> series_;  // one per kind
  std::vector<double> maxima_;                      // one per kind
  int64_t steps_ = 0;
  int64_t stride_ = 1;  // keep one step in stride_
};

}  // namespace impulse::demos
