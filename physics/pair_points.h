// A pair's points solved together: the normal rows of one manifold's N points (normal_impulse.h)
// at once, two manifolds side by side (lanes.h).
//
// Point i's row stops at its fixed point, where another pass would not change it:
//   lambda_i = max(keep_i lambda_i - push_i - mass_i vn_i, 0),
// and vn_i = vn0_i + sum_j K_ij (lambda_j - lambda0_j), K the manifold's coupling matrix. Where
// lambda_i > 0 that is  vn_i + bias_i + c_i lambda_i = 0, with bias_i = push_i / mass_i and
// c_i = (1 - keep_i) / mass_i the soft row's compliance; where lambda_i = 0 the left side may be
// positive (the point separates). A linear complementarity problem (Cottle, Pang and Stone, "The
// Linear Complementarity Problem"):
//   lambda >= 0,  f = (K + C) lambda + q >= 0,  lambda . f = 0,  q_i = vn0_i + bias_i - sum_j K_ij lambda0_j,
// whose matrix is symmetric positive definite (K is positive semidefinite, C positive; the rigid
// rows of the relax solve get a compliance of 1e-9 of their own diagonal: the four corners of a
// face are one rank short).
//
// Most pairs touch at every point and push at every point, step after step: a face at rest, a face
// landing flat. For them K + C is the same all step, and its LDL^T is prepared with the rows
// (factor_touching_points()); the solve is then a substitution, kept where no point pulls. Otherwise
// Murty's principal pivoting with the least-index rule (finite for such matrices): guess which
// points push, solve those rows by LDL^T, and flip the first point that pulls (lambda < 0) or that
// would sink (f < 0), until none does. The first guess is the points that pushed so far and those
// that would sink; a pair still apart is done without a factorization. Gauss-Seidel passes over
// the points would need tens (the four corners trade impulse slowly).
//
// A row that takes no part (a relax solve's apart point, an empty lane) keeps its impulse.
#pragma once
#include "physics/lanes.h"

namespace impulse::physics {

constexpr Real kRigidCompliance = 1e-9;  // of the row's own K_ii

// A row's compliance c_i: the soft rows' `share` of K_ii (Softness: impulse_scale / mass_scale, so
// that c_i = (1 - keep_i) / mass_i), 0 for a rigid row; and kRigidCompliance.
template <class R>
[[gnu::always_inline]] inline R row_compliance(R share, R k_ii) {
  return share * k_ii + kRigidCompliance * k_ii;
}

// LDL^T of K + C for N points that all push: L below its unit diagonal, row by row
// ((1,0) (2,0) (2,1) (3,0) (3,1) (3,2)), and 1 / D.
struct PairFactor {
  Real2 l[6];
  Real2 inv_d[4];
};
constexpr int lower(int i, int k) { return i * (i - 1) / 2 + k; }

// Lane `l` of the two factors, for `count` points whose rows all have compliance share 0 (`rigid`)
// or `soft_share` (`soft`): both at once, one in each lane of the arithmetic.
inline void factor_touching_points(PairFactor& rigid, PairFactor& soft, const Real2 (&coupling)[4][4], int count, int l, Real soft_share) {
  const Real2 share{0, soft_share};
  Real2 lower_d[4][4], inv_d[4];  // L D, and 1 / D
  for (int j = 0; j < count; ++j) {
    const Real2 k_jj = splat(coupling[j][j][l]);
    Real2 d = k_jj + row_compliance(share, k_jj);
    for (int k = 0; k < j; ++k) d = d - lower_d[j][k] * lower_d[j][k] * inv_d[k];
    inv_d[j] = select(d > 0, splat(1) / d, splat(0));
    rigid.inv_d[j][l] = inv_d[j][0];
    soft.inv_d[j][l] = inv_d[j][1];
    for (int i = j + 1; i < count; ++i) {
      Real2 lij = splat(coupling[i][j][l]);
      for (int k = 0; k < j; ++k) lij = lij - lower_d[i][k] * lower_d[j][k] * inv_d[k];
      lower_d[i][j] = lij;
      const Real2 unit = lij * inv_d[j];
      rigid.l[lower(i, j)][l] = unit[0];
      soft.l[lower(i, j)][l] = unit[1];
    }
  }
}

struct PairRowsIn {
  Real2 bias, compliance;  // each point's, as above
  Mask2 takes_part;
  Mask2 touching;  // its compliance is the one `factor` was prepared with, and the factor is the rows'
};

// The lanes not `settled`, by Murty's principal pivoting (above); `q` as above; `lambda`: the settled
// lanes' solution.
template <int N>
[[gnu::noinline]] Mask2 pivot_pair_points(const Real2 (&coupling)[4][4], const PairRowsIn (&rows)[N], const Real2 (&q)[N],
                                          const Mask2 (&takes_part)[N], Mask2 settled, Real2 (&lambda)[N], Real2 (&impulse)[N]) {
  // The first guess: the points that pushed so far, and those that would sink without more push.
  Mask2 pushes[N];
  for (int i = 0; i < N; ++i) pushes[i] = takes_part[i] & ((impulse[i] > 0) | (q[i] < 0));
  for (int iteration = 0; iteration < (1 << N) + 2; ++iteration) {
    // LDL^T of the pushing points' rows (identity where a point does not push), then its solve.
    Mask2 any_pushes = pushes[0];
    for (int i = 1; i < N; ++i) any_pushes = any_pushes | pushes[i];
    Real2 x[N] = {};
    if (any(any_pushes & ~settled)) {
      Real2 lower_d[N][N], inv_d[N];  // L D, and 1 / D
      for (int j = 0; j < N; ++j) {
        Real2 djj = select(pushes[j], coupling[j][j] + rows[j].compliance, splat(1));
        for (int k = 0; k < j; ++k) djj = djj - lower_d[j][k] * lower_d[j][k] * inv_d[k];
        inv_d[j] = splat(1) / djj;
        for (int i = j + 1; i < N; ++i) {
          Real2 mij = select(pushes[i] & pushes[j], coupling[i][j], splat(0));
          for (int k = 0; k < j; ++k) mij = mij - lower_d[i][k] * lower_d[j][k] * inv_d[k];
          lower_d[i][j] = mij;
        }
      }
      for (int i = 0; i < N; ++i) {
        Real2 y = select(pushes[i], -q[i], splat(0));
        for (int k = 0; k < i; ++k) y = y - lower_d[i][k] * inv_d[k] * x[k];
        x[i] = y;
      }
      for (int i = N - 1; i >= 0; --i) {
        Real2 y = x[i] * inv_d[i];
        for (int k = i + 1; k < N; ++k) y = y - lower_d[k][i] * inv_d[i] * x[k];
        x[i] = y;
      }
    }
    // The first point, in index order, that pulls or would sink flips; a lane where none does is
    // settled. A pushing point's f is 0 by its row.
    Mask2 flipped = Mask2{0, 0};
    for (int i = 0; i < N; ++i) {
      Mask2 wrong = pushes[i] & (x[i] < 0);
      if (any(~pushes[i])) {
        Real2 f = q[i];
        for (int j = 0; j < N; ++j) f = f + select(pushes[j], coupling[i][j] * x[j], splat(0));
        wrong = wrong | (~pushes[i] & (f < 0));
      }
      wrong = wrong & takes_part[i] & ~flipped & ~settled;
      lambda[i] = select(settled, lambda[i], select(pushes[i], x[i], splat(0)));
      pushes[i] = pushes[i] ^ wrong;
      flipped = flipped | wrong;
    }
    settled = settled | ~flipped;
    if (!any(~settled)) break;
  }
  for (int i = 0; i < N; ++i) impulse[i] = select(settled & takes_part[i], lambda[i], impulse[i]);
  return settled;
}

// `impulse` in: each point's accumulated normal impulse; out: the solution. `vn`: the normal
// velocities now; `coupling`: K; `factor`: K + C's where every point touches. Returns false in a
// lane whose pivoting did not settle (rounding at a point that neither pushes nor separates):
// that lane's `impulse` is left as it came.
template <int N>
[[gnu::always_inline]] inline Mask2 solve_pair_points(const Real2 (&coupling)[4][4], const PairFactor& factor,
                                                     const PairRowsIn (&rows)[N], const Real2 (&vn)[N], Real2 (&impulse)[N]) {
  Mask2 takes_part[N];
  Mask2 idle = ~Mask2{0, 0}, every_point_touches = ~Mask2{0, 0};
  for (int i = 0; i < N; ++i) {
    takes_part[i] = rows[i].takes_part;
    idle = idle & ~takes_part[i];
    every_point_touches = every_point_touches & takes_part[i] & rows[i].touching;
  }
  Real2 lambda[N] = {};
  Mask2 settled = idle;
  Real2 q[N];
  for (int i = 0; i < N; ++i) {
    q[i] = vn[i] + rows[i].bias;
    for (int j = 0; j < N; ++j) q[i] = q[i] - select(takes_part[j], coupling[i][j] * impulse[j], splat(0));
  }
  // Every point touching and pushing: the prepared factor. The same arithmetic as the pivoting's
  // for that guess, so that either gives the same bits.
  if (any(every_point_touches)) {
    Real2 x[N];
    for (int i = 0; i < N; ++i) {
      Real2 y = -q[i];
      for (int k = 0; k < i; ++k) y = y - factor.l[lower(i, k)] * x[k];
      x[i] = y;
    }
    for (int i = N - 1; i >= 0; --i) {
      Real2 y = x[i] * factor.inv_d[i];
      for (int k = i + 1; k < N; ++k) y = y - factor.l[lower(k, i)] * x[k];
      x[i] = y;
    }
    Mask2 pushes = every_point_touches;
    for (int i = 0; i < N; ++i) pushes = pushes & (x[i] >= 0);
    for (int i = 0; i < N; ++i) lambda[i] = select(pushes, x[i], splat(0));
    settled = settled | pushes;
    if (!any(~settled)) {
      for (int i = 0; i < N; ++i) impulse[i] = select(idle, impulse[i], lambda[i]);
      return settled;
    }
  }
  return pivot_pair_points<N>(coupling, rows, q, takes_part, settled, lambda, impulse);
}

}  // namespace impulse::physics
