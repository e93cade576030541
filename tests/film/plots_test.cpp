// The live plots (plot_recorder.h): bounded series that keep their maximum, from a chosen time.
#include "demos/film/camera_path.h"
#include "demos/film/playback_timeline.h"
#include "demos/film/plot_recorder.h"
#include "demos/scene/scene_file.h"
#include "render/palette.h"

#include <gtest/gtest.h>

#include <cmath>

#include <filesystem>
#include <fstream>

namespace impulse::demos {
namespace {

// A long video keeps its plots' memory: the series thin out, the maximum still counts every step.
TEST(Plots, SeriesStayBoundedAndKeepTheirMaximum) {
  PlotRecorder plots({PlotKind::kinetic_energy}, {});
  physics::StepRecord record;
  for (int step = 0; step < 60 * 600; ++step) {  // ten minutes at 60 steps a second
    record.time = step / 60.0;
    record.kinetic_energy = step == 12345 ? 99.0 : 1.0;
    plots.add_step(record, {});
  }
  const std::vector<render::Plot> shown = plots.plots(plots.steps(), 600, plots.maxima(), {});
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_LE(shown[0].series[0].points.size(), 2048u);
  EXPECT_GE(shown[0].series[0].points.size(), 1024u);
  EXPECT_NEAR(shown[0].series[0].points.back().x(), 600.0, 1.0);
  EXPECT_DOUBLE_EQ(plots.maxima()[0], 99.0);
}

// [overlay] plot_from: a landing's spike before it neither shows nor sets the value range, so the
// small speeds after it read.
TEST(Plots, StartFromAChosenTime) {
  PlotRecorder plots({PlotKind::kinetic_energy}, {}, 2.0);
  physics::StepRecord record;
  for (int step = 0; step < 6 * 60; ++step) {
    record.time = step / 60.0;
    record.kinetic_energy = record.time < 1 ? 50.0 : 0.1 + 0.01 * std::sin(step);
    plots.add_step(record, {});
  }
  EXPECT_NEAR(plots.maxima()[0], 0.11, 1e-3);
  const std::vector<render::Plot> shown = plots.plots(plots.steps(), 6, plots.maxima(), {});
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_FLOAT_EQ(shown[0].x_start, 2.0f);
  ASSERT_FALSE(shown[0].series[0].points.empty());
  EXPECT_GE(shown[0].series[0].points.front().x(), 2.0f);
  EXPECT_LT(shown[0].y_max, 0.2f);
}

// [overlay] plot_body = [...]: the speed plot draws a curve per body, each in the body's colour and
// with its own speed; one body keeps the plot's own colour and names it in the heading.
TEST(Plots, SeveralBodiesSpeedsACurveEachInItsColour) {
  std::vector<physics::Body> bodies(3);
  bodies[0].name = "ramp";
  bodies[1].name = "solid ball";
  bodies[2].name = "hollow ball";
  bodies[1].inv_mass = bodies[2].inv_mass = 1;
  EXPECT_EQ(plotted_bodies(bodies, {}), std::vector<int>{1});  // the first that moves
  EXPECT_EQ(plotted_bodies(bodies, {"hollow ball", "solid ball"}), (std::vector<int>{2, 1}));
  PlotRecorder plots({PlotKind::speed}, plotted_bodies(bodies, {"solid ball", "hollow ball"}));
  physics::StepRecord record;
  for (int step = 0; step < 60; ++step) {
    record.time = step / 60.0;
    bodies[1].velocity = physics::Vec3(5.0 / 7 * record.time, 0, 0);
    bodies[2].velocity = physics::Vec3(0, -3.0 / 5 * record.time, 0);
    plots.add_step(record, bodies);
  }
  const render::Colour orange{0.9f, 0.62f, 0.0f}, purple{0.8f, 0.47f, 0.65f};
  const std::vector<render::Plot> shown = plots.plots(plots.steps(), 1, plots.maxima(), {{"solid ball", orange}, {"hollow ball", purple}});
  ASSERT_EQ(shown.size(), 1u);
  ASSERT_EQ(shown[0].series.size(), 2u);
  EXPECT_EQ(shown[0].title, "speeds");
  EXPECT_FLOAT_EQ(shown[0].series[0].colour.r, orange.r);
  EXPECT_FLOAT_EQ(shown[0].series[1].colour.b, purple.b);
  EXPECT_NEAR(shown[0].series[0].points.back().y(), 5.0 / 7 * 59 / 60, 1e-6);
  EXPECT_NEAR(shown[0].series[1].points.back().y(), 3.0 / 5 * 59 / 60, 1e-6);
  EXPECT_NEAR(plots.maxima()[0], 5.0 / 7 * 59 / 60, 1e-6);  // one range for the curves

  PlotRecorder one({PlotKind::speed}, plotted_bodies(bodies, {"hollow ball"}));
  one.add_step(record, bodies);
  const std::vector<render::Plot> alone = one.plots(one.steps(), 1, one.maxima(), {{"hollow ball", purple}});
  ASSERT_EQ(alone[0].series.size(), 1u);
  EXPECT_EQ(alone[0].title, "speed of hollow ball");
  EXPECT_FLOAT_EQ(alone[0].series[0].colour.b, render::okabe_ito::bluish_green.b);  // the plot's own
}

}  // namespace
}  // namespace impulse::demos
