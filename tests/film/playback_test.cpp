// The playback timeline (playback_timeline.h): real time, half speed, slow motion around impacts.
#include "demos/film/camera_path.h"
#include "demos/film/playback_timeline.h"
#include "demos/film/plot_recorder.h"
#include "demos/scene/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>

namespace impulse::demos {
namespace {

TEST(Playback, RealTimeHasDurationTimesFpsFrames) {
  const PlaybackTimeline timeline(PlaybackOptions{}, {}, 2.0, 30);
  EXPECT_EQ(timeline.frame_count(), 60);
  EXPECT_NEAR(timeline.next_frame_time(0.5), 0.5 + 1.0 / 30, 1e-12);
  EXPECT_FALSE(timeline.slow_motion_at(1.0));
}

TEST(Playback, HalfSpeedDoublesTheFrames) {
  PlaybackOptions options;
  options.speed = 0.5;
  EXPECT_EQ(PlaybackTimeline(options, {}, 2.0, 30).frame_count(), 120);
}

TEST(Playback, SlowsAroundImpactsAndEasesBack) {
  PlaybackOptions options;
  options.slow_motion_impulse = 1.0;
  options.slow_motion_speed = 0.25;
  options.slow_motion_window = 0.2;
  const PlaybackTimeline timeline(options, {1.0}, 3.0, 30);
  EXPECT_DOUBLE_EQ(timeline.speed_at(1.0), 0.25);
  EXPECT_DOUBLE_EQ(timeline.speed_at(0.85), 0.25);           // before the impact too
  EXPECT_TRUE(timeline.slow_motion_at(1.15));
  EXPECT_GT(timeline.speed_at(1.25), 0.25);                  // easing out
  EXPECT_LT(timeline.speed_at(1.25), 1.0);
  EXPECT_DOUBLE_EQ(timeline.speed_at(2.0), 1.0);
  // 0.4 s of simulated time at a quarter speed adds about 1.2 s of video.
  EXPECT_GT(timeline.frame_count(), 90 + 36);
  EXPECT_LT(timeline.frame_count(), 90 + 36 + 12);
}

}  // namespace
}  // namespace impulse::demos
