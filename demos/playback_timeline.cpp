#include "demos/playback_timeline.h"

#include <algorithm>
#include <cmath>

namespace impulse::demos {
namespace {

constexpr double kEase = 0.1;  // s of simulated time to ease into and out of slow motion

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

}  // namespace

PlaybackTimeline::PlaybackTimeline(const PlaybackOptions& options, std::vector<double> impact_times, double duration,
                                   int fps)
    : options_(options), impact_times_(std::move(impact_times)), duration_(duration), fps_(fps) {
  std::sort(impact_times_.begin(), impact_times_.end());
  // Frame k shows time t_k; the video holds every frame that starts before the duration ends
  // (so 1 s at 30 fps is 30 frames, at times 0 .. 29/30).
  double time = 0;
  while (time < duration_ - 0.5 * speed_at(time) / fps_ && frame_count_ < 10'000'000) {
    ++frame_count_;
    time = next_frame_time(time);
  }
  frame_count_ = std::max(frame_count_, 1);
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

}  // namespace impulse::demos
