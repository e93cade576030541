// A pair's points solved together: the normal rows of one manifold's N points (normal_impulse.h)
// at once, two manifolds side by side (lanes.h).
//
// Point i's row stops at its fixed point, where another pass would not change it:
//   lambda_i = max(keep_i lambda_i - push_i - mass_i vn_i, 0),
// and vn_i = vn0_i + sum_j K_ij (lambda_j - lambda0_j), K the manifold's coupling matrix. Where
// lambda_i > 0 that is  sum_j K_ij lambda_j + c_i lambda_i + q_i = 0  with c_i = (1 - keep_i) / mass_i
// (the soft row's compliance) and q_i = vn0_i - sum_j K_ij lambda0_j + push_i / mass_i; where
// lambda_i = 0 the left side may be positive (the point separates). A linear complementarity
// problem (Cottle, Pang and Stone, "The Linear Complementarity Problem"):
//   lambda >= 0,  f = (K + C) lambda + q >= 0,  lambda . f = 0,
// whose matrix is symmetric positive definite (K is positive semidefinite, C positive; the rigid
// rows of the relax solve get a compliance of 1e-9 of their own diagonal: the four corners of a
// face are one rank short). Solved exactly by Murty's principal pivoting with the least-index
// rule (finite for such matrices): guess which points push, solve those rows by LDL^T, and flip the
// first point that pulls (lambda < 0) or that would sink (f < 0), until none does. The first
// guess is that every point pushes: a face at rest or landing flat is done in one solve, where
// Gauss-Seidel passes over the points need tens (the four corners trade impulse slowly).
//
// A row with no mass (a relax solve's apart point, an empty lane) keeps its impulse and takes no
// part.
#pragma once
#include "physics/lanes.h"

namespace impulse::physics {

struct PairRowsIn {
  Real2 mass, push, keep;  // each point's NormalRow
};

// `impulse` in: each point's accumulated normal impulse; out: the solution. `vn`: the normal
// velocities now; `coupling`: K. Returns false in a lane whose pivoting did not settle (rounding
// at a point that neither pushes nor separates): that lane's `impulse` is left as it came.
template <int N>
[[gnu::always_inline]] inline Mask2 solve_pair_points(const Real2 (&coupling)[4][4], const PairRowsIn (&rows)[N], const Real2 (&vn)[N],
                                                     Real2 (&impulse)[N]) {
  constexpr Real kRigidCompliance = 1e-9;  // of the row's own K_ii
  Mask2 takes_part[N];
  Real2 c[N], q[N];
  for (int i = 0; i < N; ++i) takes_part[i] = rows[i].mass > 0;
  for (int i = 0; i < N; ++i) {
    const Real2 mass = select(takes_part[i], rows[i].mass, splat(1));
    c[i] = (splat(1) - rows[i].keep) / mass + splat(kRigidCompliance) * coupling[i][i];
    q[i] = vn[i] + rows[i].push / mass;
    for (int j = 0; j < N; ++j) q[i] = q[i] - select(takes_part[j], coupling[i][j] * impulse[j], splat(0));
  }
  Mask2 pushes[N];
  for (int i = 0; i < N; ++i) pushes[i] = takes_part[i];
  Real2 lambda[N] = {};
  Mask2 settled = Mask2{0, 0};
  for (int iteration = 0; iteration < (1 << N) + 2; ++iteration) {
    // LDL^T of the pushing points' rows (identity where a point does not push).
    Real2 l_factor[N][N], d[N], x[N];
    for (int j = 0; j < N; ++j) {
      Real2 djj = select(pushes[j], coupling[j][j] + c[j], splat(1));
      for (int k = 0; k < j; ++k) djj = djj - l_factor[j][k] * l_factor[j][k] * d[k];
      d[j] = djj;
      for (int i = j + 1; i < N; ++i) {
        Real2 mij = select(pushes[i] & pushes[j], coupling[i][j], splat(0));
        for (int k = 0; k < j; ++k) mij = mij - l_factor[i][k] * l_factor[j][k] * d[k];
        l_factor[i][j] = mij / djj;
      }
    }
    for (int i = 0; i < N; ++i) {
      Real2 y = select(pushes[i], -q[i], splat(0));
      for (int k = 0; k < i; ++k) y = y - l_factor[i][k] * x[k];
      x[i] = y;
    }
    for (int i = N - 1; i >= 0; --i) {
      Real2 y = x[i] / d[i];
      for (int k = i + 1; k < N; ++k) y = y - l_factor[k][i] * x[k];
      x[i] = y;
    }
    // The first point, in index order, that pulls or would sink flips; a lane where none does is
    // settled.
    Mask2 flipped = Mask2{0, 0};
    for (int i = 0; i < N; ++i) {
      Real2 f = q[i];
      for (int j = 0; j < N; ++j) f = f + select(pushes[j], coupling[i][j] * x[j], splat(0));
      const Mask2 wrong = takes_part[i] & ~flipped & ~settled & ((pushes[i] & (x[i] < 0)) | (~pushes[i] & (f < 0)));
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

}  // namespace impulse::physics
