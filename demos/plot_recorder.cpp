#include "demos/plot_recorder.h"

#include <algorithm>

namespace impulse::demos {
namespace {

// Okabe-Ito colours, one per plot kind (README.md, "Colours").
render::Colour plot_colour(PlotKind kind) {
  switch (kind) {
    case PlotKind::kinetic_energy: return {0.90f, 0.62f, 0.00f};  // orange
    case PlotKind::momentum: return {0.00f, 0.45f, 0.70f};        // blue
    case PlotKind::speed: return {0.00f, 0.62f, 0.45f};           // bluish green
  }
  return {};
}

std::string plot_title(PlotKind kind, const std::string& body_name) {
  switch (kind) {
    case PlotKind::kinetic_energy: return "kinetic energy";
    case PlotKind::momentum: return "momentum |p|";
    case PlotKind::speed: return "speed of " + body_name;
  }
  return {};
}

std::string plot_unit(PlotKind kind) {
  switch (kind) {
    case PlotKind::kinetic_energy: return "J";
    case PlotKind::momentum: return "kg\u00b7m/s";
    case PlotKind::speed: return "m/s";
  }
  return {};
}

}  // namespace

int plotted_body(const std::vector<physics::Body>& bodies, const std::string& name) {
  for (size_t i = 0; i < bodies.size(); ++i)
    if (name.empty() ? !bodies[i].is_static() : bodies[i].name == name) return int(i);
  return -1;
}

PlotRecorder::PlotRecorder(std::vector<PlotKind> kinds, int body)
    : kinds_(std::move(kinds)), body_(body), series_(kinds_.size()), maxima_(kinds_.size(), 0.0) {}

void PlotRecorder::add_step(const physics::StepRecord& record, const std::vector<physics::Body>& bodies) {
  for (size_t i = 0; i < kinds_.size(); ++i) {
    double value = 0;
    switch (kinds_[i]) {
      case PlotKind::kinetic_energy: value = record.kinetic_energy; break;
      case PlotKind::momentum: value = record.linear_momentum.norm(); break;
      case PlotKind::speed: value = body_ >= 0 ? bodies[body_].velocity.norm() : 0.0; break;
    }
    maxima_[i] = std::max(maxima_[i], value);
    if (steps_ % stride_ == 0) series_[i].push_back(render::Vec2f(float(record.time), float(value)));
  }
  ++steps_;
  if (!series_.empty() && series_[0].size() >= kMaxPoints) {
    for (auto& series : series_) {
      size_t kept = 0;
      for (size_t j = 0; j < series.size(); j += 2) series[kept++] = series[j];
      series.resize(kept);
    }
    stride_ *= 2;
  }
}

std::vector<double> PlotRecorder::maxima() const { return maxima_; }

std::vector<render::Plot> PlotRecorder::plots(double duration, const std::vector<double>& maxima,
                                              const std::string& body_name) const {
  std::vector<render::Plot> plots;
  for (size_t i = 0; i < kinds_.size(); ++i) {
    render::Plot plot;
    plot.title = plot_title(kinds_[i], body_name);
    plot.unit = plot_unit(kinds_[i]);
    plot.colour = plot_colour(kinds_[i]);
    plot.x_end = float(duration);
    if (i < maxima.size() && maxima[i] > 0) plot.y_max = float(1.1 * maxima[i]);
    plot.points = series_[i];
    plots.push_back(std::move(plot));
  }
  return plots;
}

}  // namespace impulse::demos
