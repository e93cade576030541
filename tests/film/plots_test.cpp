// The live plots (plot_recorder.h): bounded series that keep their maximum, from a chosen time.
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

// A long video keeps its plots' memory: the series thin out, the maximum still counts every step.
TEST(Plots, SeriesStayBoundedAndKeepTheirMaximum) {
  PlotRecorder plots({PlotKind::kinetic_energy}, -1);
  physics::StepRecord record;
  for (int step = 0; step < 60 * 600; ++step) {  // ten minutes at 60 steps a second
    record.time = step / 60.0;
    record.kinetic_energy = step == 12345 ? 99.0 : 1.0;
    plots.add_step(record, {});
  }
  const std::vector<render::Plot> shown = plots.plots(plots.steps(), 600, plots.maxima(), "");
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_LE(shown[0].series[0].points.size(), 2048u);
  EXPECT_GE(shown[0].series[0].points.size(), 1024u);
  EXPECT_NEAR(shown[0].series[0].points.back().x(), 600.0, 1.0);
  EXPECT_DOUBLE_EQ(plots.maxima()[0], 99.0);
}

// [overlay] plot_from: a landing's spike before it neither shows nor sets the value range, so the
// small speeds after it read.
TEST(Plots, StartFromAChosenTime) {
  PlotRecorder plots({PlotKind::kinetic_energy}, -1, 2.0);
  physics::StepRecord record;
  for (int step = 0; step < 6 * 60; ++step) {
    record.time = step / 60.0;
    record.kinetic_energy = record.time < 1 ? 50.0 : 0.1 + 0.01 * std::sin(step);
    plots.add_step(record, {});
  }
  EXPECT_NEAR(plots.maxima()[0], 0.11, 1e-3);
  const std::vector<render::Plot> shown = plots.plots(plots.steps(), 6, plots.maxima(), "");
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_FLOAT_EQ(shown[0].x_start, 2.0f);
  ASSERT_FALSE(shown[0].series[0].points.empty());
  EXPECT_GE(shown[0].series[0].points.front().x(), 2.0f);
  EXPECT_LT(shown[0].y_max, 0.2f);
}

}  // namespace
}  // namespace impulse::demos
