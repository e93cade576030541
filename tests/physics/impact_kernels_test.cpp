// The impact's kernels (physics/restitution.h, friction.h) on two bodies, each checked against
// the law it computes: when the surfaces meet, where, the bodies moved there and back, and
// Coulomb's friction with maximum dissipation.
#include "physics/friction.h"
#include "physics/normal_impulse.h"
#include "physics/restitution.h"

#include <gtest/gtest.h>

#include <cmath>

namespace impulse::physics {
namespace {

using Vec2 = Eigen::Matrix<Real, 2, 1>;
using Mat2 = Eigen::Matrix<Real, 2, 2>;

constexpr Real kH = 1.0 / 240;  // a sub-step at 60 Hz and 4 sub-steps

// Without acceleration the surfaces meet after gap / speed, at the speed they close.
TEST(Meets, WithoutGravityAfterTheGapOverTheSpeed) {
  Hit hit;
  ASSERT_TRUE(meets(0.004, -2.0, 0, 0.5, 0.1, kH, hit));
  EXPECT_NEAR(hit.tau, 0.002, 1e-15);
  EXPECT_NEAR(hit.touch, -2.0, 1e-15);
  EXPECT_NEAR(hit.u, 1.0, 1e-15);       // eq. 5: -e times the speed they meet at
  EXPECT_NEAR(hit.target, 1.0, 1e-15);  // nothing changes it after
}

// Under gravity: v_touch^2 = v0^2 - 2 a gap, and gap = -(v0 + v_touch) tau / 2, from the exact
// state (x, vn - a h/2) that semi-implicit Euler's (x, vn) stands for.
TEST(Meets, UnderGravityAsTheExactMotion) {
  const Real a = -9.81, vn = -1.5, gap = 0.005;
  Hit hit;
  ASSERT_TRUE(meets(gap, vn, a, 0.8, 0.1, kH, hit));
  const Real v0 = vn - a * kH / 2;
  EXPECT_NEAR(hit.touch * hit.touch, v0 * v0 - 2 * a * gap, 1e-12);
  EXPECT_NEAR(gap, -(v0 + hit.touch) * hit.tau / 2, 1e-15);
  EXPECT_NEAR(hit.u, -0.8 * hit.touch, 1e-15);
  EXPECT_NEAR(hit.target, hit.u + a * (kH / 2 - hit.tau), 1e-15);
}

TEST(Meets, NotWhenTooSlowOrTooFar) {
  Hit hit;
  EXPECT_FALSE(meets(0.0, -0.05, 0, 1, 0.1, kH, hit));     // slower than the threshold
  EXPECT_FALSE(meets(0.01, -2.0, 0, 1, 0.1, kH, hit));     // 2 m/s closes 8.3 mm of the 10 mm
  EXPECT_TRUE(meets(-0.001, -2.0, 0, 1, 0.1, kH, hit));    // overlapping: now
  EXPECT_EQ(hit.tau, 0);
  EXPECT_EQ(hit.gap, 0);
}

// A gap closed to within kTouching at the sub-step's end is a meeting then, not one missed: the
// relax pass would stop the pair as touching and the bounce would be lost.
TEST(Meets, AGapClosedToTouchingMeetsAtTheEnd) {
  Hit hit;
  ASSERT_TRUE(meets(2.0 * kH + kTouching / 2, -2.0, 0, 1, 0.1, kH, hit));
  EXPECT_EQ(hit.tau, kH);
  EXPECT_NEAR(hit.u, 2.0, 1e-15);
}

// Moved on and back by the same time, a body is where it was; moved on, it went along v and
// turned about w as the positions' integration turns (q + t/2 w q, normalised: by 2 atan(|w| t / 2)).
TEST(Advance, OnAndBackIsWhereItWas) {
  BodyState s;
  s.v = Vec3(1, -2, 0.5);
  s.w = Vec3(3, 0, -4);
  s.inv_mass = 1;
  s.dp = Vec3(0.01, 0.02, 0.03);
  advance(s, 0.003);
  EXPECT_LT((s.dp - Vec3(0.01, 0.02, 0.03) - 0.003 * s.v).norm(), 1e-15);
  EXPECT_NEAR(s.dq.angularDistance(Quat::Identity()), 2 * std::atan(0.003 * s.w.norm() / 2), 1e-12);
  EXPECT_LT(s.dq.vec().normalized().cross(s.w.normalized()).norm(), 1e-12);
  advance(s, -0.003);
  EXPECT_LT((s.dp - Vec3(0.01, 0.02, 0.03)).norm(), 1e-15);
  EXPECT_LT(s.dq.angularDistance(Quat::Identity()), 1e-12);
}

// A ball on the ground (A the ball, B the still ground, the normal from B to A): the lever arm is
// -R n from the ball's centre at the moment of contact, whatever it has moved or spun since the
// step began.
TEST(ImpactGeometry, ASpheresPointIsBelowItsCentreHoweverItMovesAndSpins) {
  const Real radius = 0.1;
  ManifoldConstraint m;
  m.a = 0, m.b = 1, m.first = 0, m.count = 1;
  m.normal = Vec3::UnitY();
  m.radius_a = radius;
  m.turns_a = false, m.turns_b = false;
  ContactAnchors c;
  c.anchor_a = Vec3(0, -radius, 0);             // at the step's start, the ball over the origin
  c.anchor_b = Vec3::Zero();                    // the ground's point, from its centre at the origin
  BodyState ball, ground;
  ball.inv_mass = 1;
  ball.v = Vec3(2, -5, 0);
  ball.w = Vec3(0, 0, 30);
  ball.dp = Vec3(0.02, -0.05, 0);               // moved on since the step began
  BodyInertia ball_inertia, ground_inertia;
  ball_inertia.inv_inertia = Mat3::Identity() / (0.4 * radius * radius);
  const ImpactGeometry g = impact_geometry(m, &c, ball, ball_inertia, ground, ground_inertia, 0.001);
  EXPECT_LT((g.ra[0] - Vec3(0, -radius, 0)).norm(), 1e-15);
  // One world point: r_a - r_b = x_b - x_a then.
  const Vec3 ball_centre = Vec3(0, 0, 0) - c.anchor_a + ball.dp + ball.v * 0.001;
  EXPECT_LT(((ball_centre + g.ra[0]) - (Vec3::Zero() + g.rb[0])).norm(), 1e-15);
  EXPECT_LT((g.moved_a - (ball.dp + ball.v * 0.001)).norm(), 1e-15);
}

// Coulomb with maximum dissipation: inside the disc the impulse that stops the sliding
// (K (j - j0) + v = 0); outside, the point of the rim with the least energy (checked against the
// whole rim).
TEST(LeastEnergyInDisc, StopsTheSlidingWhenCoulombAllowsElseTheRimsBest) {
  Mat2 k;
  k << 3.0, 0.7, 0.7, 1.5;
  const Vec2 v(-1.2, 0.4), j0(0.05, -0.02);
  auto energy = [&](const Vec2& x) { return 0.5 * (x - j0).dot(k * (x - j0)) + (x - j0).dot(v); };
  const Vec2 stick = least_energy_in_disc(k, v, j0, 10.0);
  EXPECT_LT((k * (stick - j0) + v).norm(), 1e-12);
  const Real limit = 0.2;
  const Vec2 slide = least_energy_in_disc(k, v, j0, limit);
  EXPECT_NEAR(slide.norm(), limit, 1e-12);
  for (int i = 0; i < 3600; ++i) {
    const Real angle = 2 * M_PI * i / 3600;
    EXPECT_LE(energy(slide), energy(limit * Vec2(std::cos(angle), std::sin(angle))) + 1e-12) << angle;
  }
  EXPECT_EQ(least_energy_in_disc(k, v, j0, 0.0), Vec2::Zero());  // no friction: no impulse
}

// A sphere's tangents are uncoupled (K = k I): the rim's best is mu J straight against the
// sliding, as Routh's graphical method gives for a ball.
TEST(LeastEnergyInDisc, ForABallAgainstTheSliding) {
  const Mat2 k = 3.5 * Mat2::Identity();
  const Vec2 v(3.0, -4.0);
  const Vec2 j = least_energy_in_disc(k, v, Vec2::Zero(), 0.5);
  EXPECT_LT((j - (-0.5 * v / v.norm())).norm(), 1e-12);
}

}  // namespace
}  // namespace impulse::physics
