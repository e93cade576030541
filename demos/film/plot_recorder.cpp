#include "demos/film/plot_recorder.h"

#include <algorithm>

#include "render/palette.h"

namespace impulse::demos {
namespace {

render::Colour plot_colour(PlotKind kind) {
  switch (kind) {
    case PlotKind::kinetic_energy: return render::okabe_ito::orange;
    case PlotKind::momentum: return render::okabe_ito::blue;
    case PlotKind::speed: return render::okabe_ito::bluish_green;
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

PlotRecorder::PlotRecorder(std::vector<PlotKind> kinds, int body, double from)
    : kinds_(std::move(kinds)), body_(body), from_(from), samples_(kinds_.size()), maxima_(kinds_.size(), 0.0) {}

void PlotRecorder::add_step(const physics::StepRecord& record, const std::vector<physics::Body>& bodies) {
  for (size_t i = 0; i < kinds_.size(); ++i) {
    double value = 0;
    switch (kinds_[i]) {
      case PlotKind::kinetic_energy: value = record.kinetic_energy; break;
      case PlotKind::momentum: value = record.linear_momentum.norm(); break;
      case PlotKind::speed: value = body_ >= 0 ? bodies[body_].velocity.norm() : 0.0; break;
    }
    if (record.time >= from_) maxima_[i] = std::max(maxima_[i], value);
    samples_[i].push_back(render::Vec2f(float(record.time), float(value)));
  }
  ++steps_;
}

std::vector<render::Plot> PlotRecorder::plots(int64_t steps, double duration, const std::vector<double>& maxima,
                                              const std::string& body_name) const {
  // Every stride-th sample; the stride doubles whenever the points shown would reach kMaxPoints.
  int64_t stride = 1;
  while ((steps + stride - 1) / stride >= int64_t(kMaxPoints)) stride *= 2;
  std::vector<render::Plot> plots;
  for (size_t i = 0; i < kinds_.size(); ++i) {
    render::Plot plot;
    plot.title = plot_title(kinds_[i], body_name);
    plot.unit = plot_unit(kinds_[i]);
    render::PlotSeries& series = plot.series.emplace_back();
    series.colour = plot_colour(kinds_[i]);
    plot.x_start = float(from_);
    plot.x_end = float(duration);
    if (i < maxima.size() && maxima[i] > 0) plot.y_max = float(1.1 * maxima[i]);
    for (int64_t j = 0; j < steps && j < int64_t(samples_[i].size()); j += stride)
      if (samples_[i][j].x() >= from_) series.points.push_back(samples_[i][j]);
    plots.push_back(std::move(plot));
  }
  return plots;
}

}  // namespace impulse::demos
