// Which moment of the simulation each video frame shows. The simulation keeps its own fixed step;
// playback runs at `speed` simulated seconds per video second, and slows to `slow_motion_speed`
// around each impact (easing in and out over 0.1 s), so a bounce can be watched.
//
// Impacts may be added as the world steps: the speed at a moment depends only on the impacts
// within lookahead() of it, so it is final once the world is that far past it.
#pragma once
#include "demos/scene/view_options.h"

#include <vector>

namespace impulse::demos {

class PlaybackTimeline {
 public:
  PlaybackTimeline(const PlaybackOptions& options, double duration, int fps);
  // The same with every impact known (simulated s: when an impact strong enough happened).
  PlaybackTimeline(const PlaybackOptions& options, const std::vector<double>& impact_times, double duration, int fps);

  void add_impact(double time);  // in any order (several worlds' impacts interleave)
  double lookahead() const;      // s past a frame's moment that must be simulated before it is final

  double speed_at(double time) const;         // simulated s per video s at simulated `time`
  bool slow_motion_at(double time) const;     // within an impact's window (or easing into it)
  double next_frame_time(double time) const;  // the simulated time of the frame after one at `time`
  bool shows(double time) const;              // a frame at `time` (after the first) is part of the video
  int frame_count() const;                    // frames until the duration is shown (at least 1)

 private:
  PlaybackOptions options_;
  std::vector<double> impact_times_;  // sorted
  double duration_;
  int fps_;
};

}  // namespace impulse::demos
