// Which moment of the simulation each video frame shows. The simulation keeps its own fixed step;
// playback runs at `speed` simulated seconds per video second, and slows to `slow_motion_speed`
// around each impact (easing in and out over 0.1 s), so a bounce can be watched.
#pragma once
#include "demos/view_options.h"

#include <vector>

namespace impulse::demos {

class PlaybackTimeline {
 public:
  // `impact_times`: when (simulated s) an impact strong enough for slow motion happened.
  PlaybackTimeline(const PlaybackOptions& options, std::vector<double> impact_times, double duration, int fps);

  double speed_at(double time) const;         // simulated s per video s at simulated `time`
  bool slow_motion_at(double time) const;     // within an impact's window (or easing into it)
  double next_frame_time(double time) const;  // the simulated time of the frame after one at `time`
  int frame_count() const { return frame_count_; }  // frames until the duration is shown

 private:
  PlaybackOptions options_;
  std::vector<double> impact_times_;  // sorted
  double duration_;
  int fps_;
  int frame_count_ = 0;
};

}  // namespace impulse::demos
