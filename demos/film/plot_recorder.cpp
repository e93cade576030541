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

std::string plot_title(PlotKind kind, const std::vector<PlotCurve>& curves) {
  switch (kind) {
    case PlotKind::kinetic_energy: return "kinetic energy";
    case PlotKind::momentum: return "momentum |p|";
    case PlotKind::speed: return curves.size() == 1 ? "speed of " + curves[0].name : "speeds";
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

std::vector<int> plotted_bodies(const std::vector<physics::Body>& bodies, const std::vector<std::string>& names) {
  std::vector<int> found;
  for (const std::string& name : names)
    for (size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i].name == name) {
        found.push_back(int(i));
        break;
      }
  if (names.empty())
    for (size_t i = 0; i < bodies.size() && found.empty(); ++i)
      if (!bodies[i].is_static()) found.push_back(int(i));
  return found;
}

PlotRecorder::PlotRecorder(std::vector<PlotKind> kinds, std::vector<int> bodies, double from)
    : kinds_(std::move(kinds)), bodies_(std::move(bodies)), from_(from), samples_(kinds_.size()), maxima_(kinds_.size(), 0.0) {
  for (size_t i = 0; i < kinds_.size(); ++i) samples_[i].resize(kinds_[i] == PlotKind::speed ? std::max<size_t>(bodies_.size(), 1) : 1);
}

void PlotRecorder::add_step(const physics::StepRecord& record, const std::vector<physics::Body>& bodies) {
  for (size_t i = 0; i < kinds_.size(); ++i)
    for (size_t curve = 0; curve < samples_[i].size(); ++curve) {
      double value = 0;
      switch (kinds_[i]) {
        case PlotKind::kinetic_energy: value = record.kinetic_energy; break;
        case PlotKind::momentum: value = record.linear_momentum.norm(); break;
        case PlotKind::speed: value = curve < bodies_.size() ? bodies[size_t(bodies_[curve])].velocity.norm() : 0.0; break;
      }
      if (record.time >= from_) maxima_[i] = std::max(maxima_[i], value);
      samples_[i][curve].push_back(render::Vec2f(float(record.time), float(value)));
    }
  ++steps_;
}

std::vector<render::Plot> PlotRecorder::plots(int64_t steps, double duration, const std::vector<double>& maxima,
                                              const std::vector<PlotCurve>& curves) const {
  // Every stride-th sample; the stride doubles whenever the points shown would reach kMaxPoints.
  int64_t stride = 1;
  while ((steps + stride - 1) / stride >= int64_t(kMaxPoints)) stride *= 2;
  std::vector<render::Plot> plots;
  for (size_t i = 0; i < kinds_.size(); ++i) {
    render::Plot plot;
    plot.title = plot_title(kinds_[i], curves);
    plot.unit = plot_unit(kinds_[i]);
    plot.x_start = float(from_);
    plot.x_end = float(duration);
    if (i < maxima.size() && maxima[i] > 0) plot.y_max = float(1.1 * maxima[i]);
    for (size_t curve = 0; curve < samples_[i].size(); ++curve) {
      render::PlotSeries& series = plot.series.emplace_back();
      series.colour = samples_[i].size() > 1 && curve < curves.size() ? curves[curve].colour : plot_colour(kinds_[i]);
      const std::vector<render::Vec2f>& samples = samples_[i][curve];
      for (int64_t j = 0; j < steps && j < int64_t(samples.size()); j += stride)
        if (samples[size_t(j)].x() >= from_) series.points.push_back(samples[size_t(j)]);
    }
    plots.push_back(std::move(plot));
  }
  return plots;
}

}  // namespace impulse::demos
