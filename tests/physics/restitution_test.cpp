// Issue 3's physical laws: restitution on the ground, and a head-on hit between two spheres.
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace impulse::physics {
namespace {

int add_ground(World& world, Real restitution) {
  BodyDef ground;
  ground.name = "ground";
  ground.shape = Shape::plane(Vec3::UnitY(), 0);
  ground.material.restitution = restitution;
  return world.add_body(ground);
}

class DropRebound : public ::testing::TestWithParam<Real> {};

// A ball dropped from rest rebounds to e^2 of its drop height (v' = e v, h = v^2 / 2g).
TEST_P(DropRebound, RisesToRestitutionSquaredOfDropHeight) {
  const Real e = GetParam();
  const Real radius = 0.25, drop_height = 1.0;  // height of the ball's bottom above the ground
  World world;
  add_ground(world, 0);  // the larger restitution of the pair wins
  BodyDef ball;
  ball.name = "ball";
  ball.shape = Shape::sphere(radius);
  ball.material.restitution = e;
  ball.position = Vec3(0, radius + drop_height, 0);
  const int id = world.add_body(ball);

  bool bounced = false;
  Real peak = 0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const Body& b = world.bodies()[id];
    if (!bounced && b.velocity.y() > 0) bounced = true;
    if (bounced) {
      if (b.velocity.y() < 0) break;  // past the top of the first rebound
      peak = std::max(peak, b.position.y() - radius);
    }
  }
  ASSERT_TRUE(bounced);
  EXPECT_NEAR(peak / drop_height, e * e, 0.02 * e * e) << "e = " << e << ", rebound " << peak << " m";
}

INSTANTIATE_TEST_SUITE_P(Restitution, DropRebound, ::testing::Values(0.3, 0.7, 1.0));

// Two spheres of different mass meet head on: momentum is conserved and they separate at e times
// the speed at which they approached (eq. 5).
TEST(HeadOn, ConservesMomentumAndSeparatesAtRestitutionTimesApproach) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  World world(settings);
  BodyDef light, heavy;
  light.name = "light";
  light.shape = Shape::sphere(0.5);
  light.mass = 1.0;
  light.material.restitution = 0.8;
  light.position = Vec3(-2, 1, 0);
  light.velocity = Vec3(3, 0, 0);  // total momentum 1.5 kg m/s
  heavy = light;
  heavy.name = "heavy";
  heavy.mass = 3.0;
  heavy.position = Vec3(2, 1, 0);
  heavy.velocity = Vec3(-0.5, 0, 0);
  const int a = world.add_body(light);
  const int b = world.add_body(heavy);

  const Vec3 momentum_before = 1.0 * light.velocity + 3.0 * heavy.velocity;
  const Real approach = (light.velocity - heavy.velocity).norm();
  bool hit = false;
  for (int i = 0; i < 120; ++i) {
    world.step();
    const StepRecord& record = world.record();
    hit = hit || !record.contacts.empty();
  }
  ASSERT_TRUE(hit);
  const Body& la = world.bodies()[a];
  const Body& hb = world.bodies()[b];
  const Vec3 momentum_after = la.mass * la.velocity + hb.mass * hb.velocity;
  EXPECT_LT((momentum_after - momentum_before).norm() / momentum_before.norm(), 1e-6);
  const Real separation_speed = hb.velocity.x() - la.velocity.x();
  EXPECT_NEAR(separation_speed, 0.8 * approach, 1e-4);
  EXPECT_LT(la.velocity.x(), 0);  // the light one bounces back
}

// A billiard ball that has slid along the cloth spins (up to rolling, v / R = 200 rad/s here), and
// a frictionless hit acts along the line of centres whatever the spin: the cue ball stops, the
// struck ball leaves at its speed (e = 1, equal masses), and neither spin changes. The hit's
// anchors do not turn with a sphere: turned with the cue ball (3 rad in a step), they gave both
// balls 100 rad/s of spin, and with 24 sub-steps a plastic hit.
TEST(HeadOn, ASpinningBallHitsAlongTheLineOfCentres) {
  for (int substeps : {4, 12, 24})
    for (Real spin : {0.0, -27.0, -200.0}) {
      WorldSettings settings;
      settings.substeps = settings.min_substeps = substeps;
      World world(settings);
      add_ground(world, 0);
      world.body(0).material.friction = 0;
      const Real radius = 0.028575;
      BodyDef cue;
      cue.shape = Shape::sphere(radius);
      cue.mass = 0.17;
      cue.material = {1, 0};
      cue.position = Vec3(-0.3, radius, 0);
      cue.velocity = Vec3(5.7, 0, 0);
      cue.angular_velocity = Vec3(0, 0, spin);
      world.add_body(cue);
      BodyDef red = cue;
      red.position = Vec3(0, radius, 0);
      red.velocity = red.angular_velocity = Vec3::Zero();
      world.add_body(red);
      for (int step = 0; step < 8; ++step) world.step();
      SCOPED_TRACE(::testing::Message() << substeps << " sub-steps, spin " << spin);
      EXPECT_NEAR(world.bodies()[1].velocity.x(), 0, 1e-3);
      EXPECT_NEAR(world.bodies()[2].velocity.x(), 5.7, 1e-3);
      EXPECT_NEAR(world.bodies()[1].angular_velocity.z(), spin, 1e-6);
      EXPECT_NEAR(world.bodies()[2].angular_velocity.norm(), 0, 1e-6);
    }
}

// A touching rack of `rows` rows of equal balls, e = 1, frictionless, and a cue ball of the same
// at `cue_at` moving at `cue_velocity`: the share of the cue ball's kinetic energy there after
// `steps` steps.
Real rack_energy_kept(const WorldSettings& settings, int rows, Real radius, Real mass, const Vec3& cue_at,
                      const Vec3& cue_velocity, int steps) {
  World world(settings);
  const Real pitch = 2 * radius, row_pitch = pitch * std::sqrt(Real(3)) / 2;
  BodyDef ball;
  ball.shape = Shape::sphere(radius);
  ball.mass = mass;
  ball.material = {1, 0};
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k <= row; ++k) {
      ball.position = Vec3(row * row_pitch, (k - row / Real(2)) * pitch, 0);
      world.add_body(ball);
    }
  ball.position = cue_at;
  ball.velocity = cue_velocity;
  world.add_body(ball);
  for (int step = 0; step < steps; ++step) world.step();
  Real after = 0;
  for (const Body& body : world.bodies()) after += 0.5 * mass * body.velocity.squaredNorm();
  return after / (0.5 * mass * cue_velocity.squaredNorm());
}

// A touching rack of six equal balls in zero gravity, e = 1, frictionless, struck a little off
// the line of centres: every pair the hit runs through meets elastically, so the kinetic energy
// stays what the cue ball brought. The apex's two pairs meet near the end of a sub-step: they
// bounce then, along the line of centres at that moment, rather than past the sub-step's end in
// the relax pass's inelastic rows (restitution.h, meets_at).
TEST(HeadOn, ATouchingRackStruckOffCentreKeepsItsEnergy) {
  for (int substeps : {4, 8, 12, 16}) {
    WorldSettings settings;
    settings.gravity = Vec3::Zero();
    settings.substeps = settings.min_substeps = substeps;
    EXPECT_NEAR(rack_energy_kept(settings, 3, 0.0228374, 1.89, Vec3(-0.22, -0.0205, 0), Vec3(6.984, 0.6493, 0), 6), 1, 1e-3)
        << substeps << " sub-steps";
  }
}

// A touching rack of fifteen in zero gravity, e = 1, frictionless, struck off-centre: its pairs
// press each other by rounding alone (1e-17 N s) while it waits, which is no load. A pair the hit
// runs through bounces, and bounces again when a later hit closes it within the same step, as
// any pair no load holds together may; so the energy the cue ball brought stays.
TEST(HeadOn, ARackPressedByRoundingAloneBouncesAgainWithinAStep) {
  WorldSettings settings;
  settings.gravity = Vec3::Zero();
  settings.sleep.enabled = false;
  EXPECT_NEAR(rack_energy_kept(settings, 5, 0.029340411493691702, 0.31242112310010761,
                               Vec3(-0.22543756880277716, 0.041357740962815193, 0),
                               Vec3(6.4145629115814371, -1.1767862503829423, 0), 12),
              1, 1e-3);
}

}  // namespace
}  // namespace impulse::physics
