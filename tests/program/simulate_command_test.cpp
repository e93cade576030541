// `impulse simulate`: its CSV keeps a head-on hit's momentum and gives eq. 8's velocities, from the
// starting state on.
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"

#include <gtest/gtest.h>

namespace impulse {
namespace {

using namespace testing;

TEST(Simulate, AHeadOnHitKeepsMomentumAndExchangesItAsEquationEightSays) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "head_on.toml") << kHeadOn;
  const testing::ProgramRun result = run_in_process({"simulate", (dir / "head_on.toml").string(), "--trace",
                                               (dir / "bodies.csv").string(), "--world", (dir / "world.csv").string()});
  ASSERT_TRUE(result.succeeded()) << result.describe();

  const auto world = read_csv(dir / "world.csv");
  ASSERT_EQ(world.size(), 121u);  // the start, then 2 s at 60 steps a second
  for (const auto& row : world) EXPECT_NEAR(number(row, "px_kg_m_per_s"), 3.0, 1e-9) << "step " << row.at("step");
  // Elastic: v1' = (m1 - m2) / (m1 + m2) v1 = -1 m/s, v2' = 2 m1 / (m1 + m2) v1 = 2 m/s.
  const auto bodies = read_csv(dir / "bodies.csv");
  EXPECT_NEAR(number(last_of(bodies, "light"), "vx_m_per_s"), -1.0, 1e-3);
  EXPECT_NEAR(number(last_of(bodies, "heavy"), "vx_m_per_s"), 2.0, 1e-3);
  // The trace begins with the starting state, at step 0, as the scene file gives it.
  EXPECT_EQ(bodies.front().at("body"), "\"light\"");
  EXPECT_EQ(number(bodies.front(), "time_s"), 0.0);
  EXPECT_EQ(number(bodies.front(), "step"), 0.0);
  EXPECT_EQ(number(bodies.front(), "x_m"), -2.0);
  EXPECT_EQ(number(bodies.front(), "vx_m_per_s"), 3.0);
  EXPECT_EQ(number(world.front(), "time_s"), 0.0);
  EXPECT_EQ(number(world.front(), "kinetic_energy_J"), 4.5);
  EXPECT_NEAR(number(world[1], "time_s"), 1.0 / 60, 1e-9);
}

}  // namespace
}  // namespace impulse
