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
// Which points push changes seldom: a face at rest pushes at every point step after step, a face
// tilted a little pushes at the corners that touch. K + C is the same all step, so each solve of a
// lane keeps the LDL^T of the points that pushed last (PairFactors; at the step's start, every point
// touching and pushing: factor_touching_points()), and the solve is a substitution, kept where it
// meets the conditions: no pushing point pulls, no other would sink. Otherwise Murty's principal
// pivoting with the least-index rule (finite for such matrices): guess which points push, solve
// those rows by LDL^T, and flip the first point that pulls (lambda < 0) or that would sink (f < 0),
// until none does; its last factor is kept. The first guess is the points that pushed so far and
// those that would sink; a pair still apart, neither, is done without a factorization. The solution
// is unique (K + C is positive definite), so the kept factor finds what the pivoting would, in the
// same arithmetic. Gauss-Seidel passes over the points would need tens (the four corners trade
// impulse slowly).
//
// A row that takes no part (a relax solve's apart point, an empty lane) keeps its impulse.
#pragma once
#include "physics/lanes.h"

#include <cstdint>

namespace impulse::physics {

constexpr Real kRigidCompliance = 1e-9;  // of the row's own K_ii

// A row's compliance c_i: the soft rows' `share` of K_ii (Softness: impulse_scale / mass_scale, so
// that c_i = (1 - keep_i) / mass_i), 0 for a rigid row; and kRigidCompliance.
template <class R>
[[gnu::always_inline]] inline R row_compliance(R share, R k_ii) {
  return share * k_ii + kRigidCompliance * k_ii;
}

// LDL^T of K + C over the points that push: L below its unit diagonal, row by row
// ((1,0) (2,0) (2,1) (3,0) (3,1) (3,2)), and 1 / D; the rows and columns of the other points those
// of the identity.
struct PairFactor {
  Real2 l[6];
  Real2 inv_d[4];
};
constexpr int lower(int i, int k) { return i * (i - 1) / 2 + k; }

// The factor each lane of a solve last used, and the points it was made for: bit i, point i
// pushes; bit 4 + i, it pushes touching (its row's compliance the touching one). 0 in a lane: none.
struct PairFactors {
  PairFactor factor;
  uint8_t pattern[2] = {0, 0};
};
constexpr uint8_t every_point_touching(int count) { return uint8_t((1 << count) - 1) * 17; }

// Lane `l` of the two solves' factors, for `count` points that all touch and push, their rows'
// compliance share 0 (`rigid`) or `soft_share` (`soft`): both at once, one in each lane of the arithmetic.
inline void factor_touching_points(PairFactors& rigid, PairFactors& soft, const Real2 (&coupling)[4][4], int count, int l, Real soft_share) {
  const Real2 share{0, soft_share};
  Real2 lower_d[4][4], inv_d[4];  // L D, and 1 / D
  for (int j = 0; j < count; ++j) {
    const Real2 k_jj = splat(coupling[j][j][l]);
    Real2 d = k_jj + row_compliance(share, k_jj);
    for (int k = 0; k < j; ++k) d = d - lower_d[j][k] * lower_d[j][k] * inv_d[k];
    inv_d[j] = select(d > 0, splat(1) / d, splat(0));
    rigid.factor.inv_d[j][l] = inv_d[j][0];
    soft.factor.inv_d[j][l] = inv_d[j][1];
    for (int i = j + 1; i < count; ++i) {
      Real2 lij = splat(coupling[i][j][l]);
      for (int k = 0; k < j; ++k) lij = lij - lower_d[i][k] * lower_d[j][k] * inv_d[k];
      lower_d[i][j] = lij;
      const Real2 unit = lij * inv_d[j];
      rigid.factor.l[lower(i, j)][l] = unit[0];
      soft.factor.l[lower(i, j)][l] = unit[1];
    }
  }
  rigid.pattern[l] = soft.pattern[l] = every_point_touching(count);
}

struct PairRowsIn {
  Real2 bias, compliance;  // each point's, as above
  Mask2 takes_part;
  Mask2 touching;  // its compliance is the touching one
};

// Lane by lane: the points' bits of `pattern` (bit `shift` + i: point i) as masks.
template <int N>
[[gnu::always_inline]] inline void pattern_masks(const uint8_t (&pattern)[2], int shift, Mask2 (&masks)[N]) {
  const Mask2 bits{pattern[0] >> shift, pattern[1] >> shift};
  for (int i = 0; i < N; ++i) masks[i] = (bits & (1 << i)) != 0;
}

// Where a point that does not push would be, f = (K + C) lambda + q, given the pushing points' `x`
// (0 at the others).
template <int N>
[[gnu::always_inline]] inline Real2 sinking(const Real2 (&coupling)[4][4], const Real2 (&q)[N], const Real2 (&x)[N], int i) {
  Real2 f = q[i];
  for (int j = 0; j < N; ++j) f = f + coupling[i][j] * x[j];
  return f;
}

// The lanes not `settled`, by Murty's principal pivoting (above); `q` as above; `lambda`: the settled
// lanes' solution. Each lane it settles keeps its last factor in `kept`.
template <int N>
[[gnu::noinline]] Mask2 pivot_pair_points(const Real2 (&coupling)[4][4], const PairRowsIn (&rows)[N], const Real2 (&q)[N],
                                          const Mask2 (&takes_part)[N], Mask2 settled, Real2 (&lambda)[N], Real2 (&impulse)[N],
                                          PairFactors& kept) {
  // The first guess: the points that pushed so far, and those that would sink without more push.
  Mask2 pushes[N];
  for (int i = 0; i < N; ++i) pushes[i] = takes_part[i] & ((impulse[i] > 0) | (q[i] < 0));
  for (int iteration = 0; iteration < (1 << N) + 2; ++iteration) {
    // LDL^T of the pushing points' rows (identity where a point does not push), then its solve.
    Mask2 any_pushes = pushes[0];
    for (int i = 1; i < N; ++i) any_pushes = any_pushes | pushes[i];
    Real2 x[N] = {};
    Real2 lower_d[N][N] = {}, inv_d[N] = {};  // L D, and 1 / D
    const bool factored = any(any_pushes & ~settled);
    if (factored) {
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
    const Mask2 was_settled = settled;
    uint8_t pattern[2] = {0, 0};
    for (int i = 0; i < N; ++i) {
      Mask2 wrong = pushes[i] & (x[i] < 0);
      if (any(~pushes[i])) wrong = wrong | (~pushes[i] & (sinking<N>(coupling, q, x, i) < 0));
      wrong = wrong & takes_part[i] & ~flipped & ~settled;
      lambda[i] = select(settled, lambda[i], select(pushes[i], x[i], splat(0)));
      for (int l = 0; l < 2; ++l) pattern[l] |= uint8_t((pushes[i][l] ? 1 : 0) << i | (pushes[i][l] && rows[i].touching[l] ? 16 : 0) << i);
      pushes[i] = pushes[i] ^ wrong;
      flipped = flipped | wrong;
    }
    settled = settled | ~flipped;
    for (int l = 0; l < 2; ++l) {
      if (was_settled[l] || !settled[l]) continue;
      kept.pattern[l] = factored ? pattern[l] : 0;
      if (!factored) continue;
      for (int j = 0; j < N; ++j) {
        kept.factor.inv_d[j][l] = inv_d[j][l];
        for (int i = j + 1; i < N; ++i) kept.factor.l[lower(i, j)][l] = lower_d[i][j][l] * inv_d[j][l];
      }
    }
    if (!any(~settled)) break;
  }
  for (int i = 0; i < N; ++i) impulse[i] = select(settled & takes_part[i], lambda[i], impulse[i]);
  return settled;
}

// `impulse` in: each point's accumulated normal impulse; out: the solution. `vn`: the normal
// velocities now; `coupling`: K; `kept`: the factors this solve of the lanes last used. Returns
// false in a lane whose pivoting did not settle (rounding at a point that neither pushes nor
// separates): that lane's `impulse` is left as it came.
template <int N>
[[gnu::always_inline]] inline Mask2 solve_pair_points(const Real2 (&coupling)[4][4], PairFactors& kept, const PairRowsIn (&rows)[N],
                                                     const Real2 (&vn)[N], Real2 (&impulse)[N]) {
  Mask2 takes_part[N];
  Mask2 idle = ~Mask2{0, 0};
  for (int i = 0; i < N; ++i) {
    takes_part[i] = rows[i].takes_part;
    idle = idle & ~takes_part[i];
  }
  // A pair that did not push and would not sink (still apart, as a stack's side neighbours) stays
  // at 0: the pivoting's first guess, settled at once.
  Real2 q[N], pushed[N];
  for (int j = 0; j < N; ++j) pushed[j] = select(takes_part[j], impulse[j], splat(0));
  Mask2 stays_apart = ~Mask2{0, 0};
  for (int i = 0; i < N; ++i) {
    q[i] = vn[i] + rows[i].bias;
    for (int j = 0; j < N; ++j) q[i] = q[i] - coupling[i][j] * pushed[j];
    stays_apart = stays_apart & ~(takes_part[i] & ((impulse[i] > 0) | (q[i] < 0)));
  }
  Real2 lambda[N] = {};
  Mask2 settled = idle | stays_apart;
  // The kept factor, where its points still take part with the same compliance, and its solution
  // meets the conditions. The same arithmetic as the pivoting's for that guess.
  Mask2 pushes[N], pushes_touching[N];
  pattern_masks<N>(kept.pattern, 0, pushes);
  pattern_masks<N>(kept.pattern, 4, pushes_touching);
  Mask2 by_factor = ~settled & Mask2{kept.pattern[0] ? -1 : 0, kept.pattern[1] ? -1 : 0};
  for (int i = 0; i < N; ++i) by_factor = by_factor & ~(pushes[i] & (~takes_part[i] | (rows[i].touching ^ pushes_touching[i])));
  if (any(by_factor)) {
    Real2 x[N];
    for (int i = 0; i < N; ++i) {
      Real2 y = select(pushes[i], -q[i], splat(0));
      for (int k = 0; k < i; ++k) y = y - kept.factor.l[lower(i, k)] * x[k];
      x[i] = y;
    }
    for (int i = N - 1; i >= 0; --i) {
      Real2 y = x[i] * kept.factor.inv_d[i];
      for (int k = i + 1; k < N; ++k) y = y - kept.factor.l[lower(k, i)] * x[k];
      x[i] = y;
    }
    Mask2 met = by_factor;
    for (int i = 0; i < N; ++i) {
      met = met & ~(pushes[i] & (x[i] < 0));
      if (any(~pushes[i] & met)) met = met & ~(~pushes[i] & takes_part[i] & (sinking<N>(coupling, q, x, i) < 0));
    }
    for (int i = 0; i < N; ++i) lambda[i] = select(met & pushes[i], x[i], splat(0));
    settled = settled | met;
  }
  if (!any(~settled)) {
    for (int i = 0; i < N; ++i) impulse[i] = select(takes_part[i], lambda[i], impulse[i]);
    return settled;
  }
  return pivot_pair_points<N>(coupling, rows, q, takes_part, settled, lambda, impulse, kept);
}

}  // namespace impulse::physics
