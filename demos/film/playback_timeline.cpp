#include "demos/film/playback_timeline.h"

#include <algorithm>
#include <cmath>

namespace impulse::demos {
namespace {

constexpr double kEase = 0.1;  // s of simulated time to ease into and out of slow motion
constexpr int kMostFrames = 10'000'000;

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

}  // namespace

PlaybackTimeline::PlaybackTimeline(const PlaybackOptions& options, double duration, int fps)
    : options_(options), duration_(duration), fps_(fps) {}

PlaybackTimeline::PlaybackTimeline(const PlaybackOptions& options, const std::vector<double>& impact_times,
                                   double duration, int fps)
    : PlaybackTimeline(options, duration, fps) {
  impact_times_ = impact_times;
  std::sort(impact_times_.begin(), impact_times_.end());
}

void PlaybackTimeline::add_impact(double time) {
  impact_times_.insert(std::upper_bound(impact_times_.begin(), impact_times_.end(), time), time);
}

// speed_at(t) reads the impacts within the window and the ease of t; the next frame's time reads
// it half a frame on.
double PlaybackTimeline::lookahead() const {
  return options_.slow_motion_window + kEase + std::max(options_.speed, 0.0) / fps_;
}

double PlaybackTimeline::speed_at(double time) const {
  if (options_.slow_motion_impulse <= 0 || impact_times_.empty()) return options_.speed;
  // How far into slow motion: 1 inside a window, easing to 0 over kEase outside it.
  double weight = 0;
  const auto next = std::lower_bound(impact_times_.begin(), impact_times_.end(), time);
  for (auto it : {next, next == impact_times_.begin() ? next : std::prev(next)}) {
    if (it == impact_times_.end()) continue;
    const double outside = std::abs(time - *it) - options_.slow_motion_window;
    weight = std::max(weight, 1.0 - smoothstep(outside / kEase));
  }
  const double slow = std::min(options_.slow_motion_speed, options_.speed);
  return options_.speed + (slow - options_.speed) * weight;
}

bool PlaybackTimeline::slow_motion_at(double time) const { return speed_at(time) < options_.speed * 0.999; }

double PlaybackTimeline::next_frame_time(double time) const {
  // Midpoint rule: the speed changes smoothly, so this is close to the exact integral.
  const double step = 1.0 / fps_;
  const double half = time + 0.5 * step * speed_at(time);
  return time + step * speed_at(half);
}

// Frame k shows time t_k; the video holds every frame that starts before the duration ends (so
// 1 s at 30 fps is 30 frames, at times 0 .. 29/30).
bool PlaybackTimeline::shows(double time) const { return time < duration_ - 0.5 * speed_at(time) / fps_; }

int PlaybackTimeline::frame_count() const {
  int count = 0;
  for (double time = 0; shows(time) && count < kMostFrames; time = next_frame_time(time)) ++count;
  return std::max(count, 1);
}

}  // namespace impulse::demos
