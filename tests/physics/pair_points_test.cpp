// A pair's points solved together (physics/pair_points.h), checked by the conditions it solves:
// no point pulls, none sinks, and a point that pushes stops at its row's fixed point; and the
// same impulses as Gauss-Seidel passes run until they agree. The problems are a body's corners
// against the ground: the coupling of N points on a face of a body of random mass, inertia and
// orientation, the rows soft (the biased solve's) or rigid (the relax solve's), the points some
// apart and some touching, or all touching (the prepared factor's case).
#include "physics/pair_points.h"

#include "physics/normal_impulse.h"
#include "physics/softness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace impulse::physics {
namespace {

struct Problem {
  Real2 coupling[4][4] = {};
  NormalRow rows[4];
  PairRowsIn in[4];
  PairFactors factors;  // every point touching
  Real2 vn[4], impulse[4];
};

// N points of a random box face, random velocities and accumulated impulses, two lanes; every
// point touching, or some apart.
const Softness softness = make_softness(30, 10, 1.0 / 240);

template <int N>
Problem random_problem(std::mt19937& rng, bool soft, bool touching) {
  std::uniform_real_distribution<Real> u(-1, 1);
  Problem p;
  for (int l = 0; l < 2; ++l) {
    const Real inv_mass = 1 / (0.1 + 5 * (u(rng) + 1));
    const Mat3 inv_inertia = Vec3(1 + u(rng), 1 + u(rng), 1 + u(rng)).cwiseAbs().asDiagonal() * (3 * inv_mass);
    const Quat turn = Quat(u(rng), u(rng), u(rng), u(rng)).normalized();
    const Mat3 r = turn.toRotationMatrix(), world_inv_inertia = r * inv_inertia * r.transpose();
    const Vec3 n(0, 1, 0);
    const Real hx = 0.05 + 0.5 * (u(rng) + 1), hz = 0.05 + 0.5 * (u(rng) + 1);
    const Vec3 corners[4] = {{hx, -0.2, hz}, {-hx, -0.2, hz}, {-hx, -0.2, -hz}, {hx, -0.2, -hz}};
    Vec3 ra[4];
    for (int i = 0; i < N; ++i) ra[i] = r * corners[i];
        for (int i = 0; i < N; ++i) {
      for (int j = 0; j < N; ++j) {
        const Vec3 angular_j = world_inv_inertia * ra[j].cross(n);
        p.coupling[i][j][l] = inv_mass + ra[i].cross(n).dot(angular_j);
      }
      const Real normal_mass = 1 / p.coupling[i][i][l];
      const Real separation = touching ? -0.002 * std::abs(u(rng)) : 0.002 * u(rng);
      const bool apart = separation > kTouching;
      if (soft) {
        const Real bias = apart ? separation * 240 : std::max(softness.bias_rate * separation, -3.0);
        const Real mass = apart ? normal_mass : normal_mass * softness.mass_scale;
        p.rows[i].mass[l] = mass;
        p.rows[i].push[l] = mass * bias;
        p.rows[i].keep[l] = apart ? 1 : 1 - softness.impulse_scale;
        p.rows[i].bias[l] = bias;
      } else {
        p.rows[i].mass[l] = normal_mass;
        p.rows[i].push[l] = 0;
        p.rows[i].keep[l] = 1;
        p.rows[i].bias[l] = 0;
      }
      p.rows[i].touching[l] = soft && apart ? 0 : -1;
      p.vn[i][l] = 3 * u(rng);
      p.impulse[i][l] = std::max(u(rng), Real(0));
    }
    PairFactors rigid, soft_factors;
    factor_touching_points(rigid, soft_factors, p.coupling, N, l, soft_share(softness));
    const PairFactors& mine = soft ? soft_factors : rigid;
    for (int k = 0; k < 6; ++k) p.factors.factor.l[k][l] = mine.factor.l[k][l];
    for (int k = 0; k < 4; ++k) p.factors.factor.inv_d[k][l] = mine.factor.inv_d[k][l];
    p.factors.pattern[l] = mine.pattern[l];
  }
  // As the solver passes its rows (contact_solve.cpp).
  const Real2 share = splat(soft ? soft_share(softness) : 0);
  for (int i = 0; i < N; ++i)
    p.in[i] = {p.rows[i].bias, row_compliance(select(p.rows[i].touching, share, splat(0)), p.coupling[i][i]), p.rows[i].mass > 0,
               p.rows[i].touching};
  return p;
}

// Each lane's normal velocities after `impulse`.
template <int N>
void velocities_after(const Problem& p, const Real2 (&impulse)[N], Real2 (&vn)[N]) {
  for (int i = 0; i < N; ++i) {
    vn[i] = p.vn[i];
    for (int j = 0; j < N; ++j) vn[i] = vn[i] + p.coupling[i][j] * (impulse[j] - p.impulse[j]);
  }
}

template <int N>
void check_many(bool soft, bool touching) {
  std::mt19937 rng(N * 4 + soft * 2 + touching);
  int checked = 0, kept_new = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Problem p = random_problem<N>(rng, soft, touching);
    PairRowsIn in[N];
    NormalRow rows[N];
    Real2 vn[N], impulse[N], gauss_seidel[N];
    for (int i = 0; i < N; ++i) in[i] = p.in[i], rows[i] = p.rows[i], vn[i] = p.vn[i], impulse[i] = gauss_seidel[i] = p.impulse[i];
    PairFactors kept = p.factors;
    const Mask2 settled = solve_pair_points<N>(p.coupling, kept, in, vn, impulse);
    // Solved again by the factor it kept: the same bits. And without a factor, by the pivoting alone.
    for (int l = 0; l < 2; ++l) kept_new += kept.pattern[l] != 0 && kept.pattern[l] != p.factors.pattern[l];
    for (PairFactors again : {kept, PairFactors{}}) {
      Real2 impulse_again[N];
      for (int i = 0; i < N; ++i) impulse_again[i] = p.impulse[i];
      const Mask2 settled_again = solve_pair_points<N>(p.coupling, again, in, vn, impulse_again);
      for (int l = 0; l < 2; ++l) {
        ASSERT_EQ(settled_again[l], settled[l]) << "trial " << trial;
        for (int i = 0; i < N; ++i) ASSERT_EQ(impulse_again[i][l], impulse[i][l]) << "trial " << trial << " point " << i;
      }
    }
    Real2 after[N];
    velocities_after<N>(p, impulse, after);
    // Gauss-Seidel until nothing moves, from the same start.
    Real2 gs_vn[N];
    for (int i = 0; i < N; ++i) gs_vn[i] = p.vn[i];
    for (int pass = 0; pass < 100000; ++pass) {
      Real change = 0;
      for (int k = 0; k < N; ++k) {
        const Real2 applied = clamped_normal_impulse(rows[k], gauss_seidel[k], gs_vn[k]) - gauss_seidel[k];
        gauss_seidel[k] = gauss_seidel[k] + applied;
        for (int j = 0; j < N; ++j) gs_vn[j] = gs_vn[j] + p.coupling[j][k] * applied;
        change = std::max({change, std::abs(applied[0]), std::abs(applied[1])});
      }
      if (change < 1e-14) break;
    }
    for (int l = 0; l < 2; ++l) {
      ASSERT_TRUE(settled[l]) << "trial " << trial;
      Real largest = 1;
      for (int i = 0; i < N; ++i) largest = std::max(largest, impulse[i][l]);
      for (int i = 0; i < N; ++i) {
        const Real mass = rows[i].mass[l], lambda = impulse[i][l];
        // Where the point would be after one more pass: unchanged.
        const Real again = std::max(rows[i].keep[l] * lambda - rows[i].push[l] - mass * after[i][l], Real(0));
        EXPECT_GE(lambda, 0) << "trial " << trial << " point " << i;
        EXPECT_NEAR(again, lambda, 1e-7 * largest) << "trial " << trial << " point " << i;
        // The velocities agree with Gauss-Seidel's (the impulses may differ along a face's
        // one free mode, which moves nothing).
        EXPECT_NEAR(after[i][l], gs_vn[i][l], 1e-6) << "trial " << trial << " point " << i;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 2000 * 2 * N);
  EXPECT_GT(kept_new, 100) << "the pivoting kept too few factors of its own for the test to mean much";
}

// The prepared factors are K + C's, soft and rigid: L D L^T rebuilt agrees with it, entry by entry.
TEST(PairPoints, TheTouchingFactorsRebuildTheirMatrices) {
  std::mt19937 rng(7);
  for (const bool soft : {false, true}) {
    const Real share = soft ? soft_share(softness) : 0;
    for (int trial = 0; trial < 500; ++trial) {
      const Problem p = random_problem<4>(rng, soft, true);
      for (int l = 0; l < 2; ++l) {
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j <= i; ++j) {
            Real sum = 0;  // (L D L^T)_ij = sum_k L_ik D_k L_jk, L's diagonal 1
            for (int k = 0; k <= j; ++k) {
              const Real lik = k == i ? 1 : p.factors.factor.l[lower(i, k)][l], ljk = k == j ? 1 : p.factors.factor.l[lower(j, k)][l];
              sum += lik * ljk / p.factors.factor.inv_d[k][l];
            }
            const Real expected = p.coupling[i][j][l] + (i == j ? row_compliance(share, p.coupling[i][i][l]) : 0);
            EXPECT_NEAR(sum, expected, 1e-12 * std::abs(p.coupling[0][0][l])) << (soft ? "soft" : "rigid") << " trial " << trial << " (" << i << ", " << j << ")";
          }
      }
    }
  }
}

TEST(PairPoints, TwoSoftPointsStopAtTheirRowsFixedPoints) { check_many<2>(true, false); }
TEST(PairPoints, FourSoftPointsStopAtTheirRowsFixedPoints) { check_many<4>(true, false); }
TEST(PairPoints, ThreeRigidPointsStopAtTheirRowsFixedPoints) { check_many<3>(false, false); }
TEST(PairPoints, FourRigidCornersOfAFaceStopAtTheirRowsFixedPoints) { check_many<4>(false, false); }
// Every point touching: the prepared factor's solve where no point pulls, the pivoting where one does.
TEST(PairPoints, FourSoftTouchingCornersStopAtTheirRowsFixedPoints) { check_many<4>(true, true); }
TEST(PairPoints, ThreeSoftTouchingPointsStopAtTheirRowsFixedPoints) { check_many<3>(true, true); }

}  // namespace
}  // namespace impulse::physics
