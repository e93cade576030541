// The normal impulse (eq. 13, with 1 + e as ERRATA.md corrects it):
//
//   J = -(1 + e) v_ab . n / ( n.n (1/m_a + 1/m_b) + [(I_a^-1 (r_a x n)) x r_a + (I_b^-1 (r_b x n)) x r_b] . n )
//
// Its denominator is the inverse of the pair's effective mass along n; every impulse along one
// direction in this engine divides by it (contacts' normal and friction rows, bounces, joints'
// axial rows, the workshop's listing). The numerator's forms are the methods': the default's soft
// row below (target "stop approaching", restitution answered in restitution.cpp), and the
// listing's verbatim form (workshop_listing.cpp).
#pragma once
#include "physics/body_state.h"
#include "physics/lanes.h"
#include "physics/softness.h"

namespace impulse::physics {

// eq. 13's denominator as printed: n.n (1/m_a + 1/m_b) + n . [(I_a^-1 (r_a x n)) x r_a + ...], along
// any direction d. `d_dot_d` is the printed n.n; the solver's directions are unit and pass 1 (which
// multiplies exactly, so the result is 1/m_a + 1/m_b + d . [...]).
inline Real inverse_effective_mass(Real inv_mass_a, const Mat3& inv_inertia_a, Real inv_mass_b, const Mat3& inv_inertia_b,
                                   const Vec3& ra, const Vec3& rb, const Vec3& d, Real d_dot_d = 1) {
  const Vec3 ang_a = (inv_inertia_a * ra.cross(d)).cross(ra);
  const Vec3 ang_b = (inv_inertia_b * rb.cross(d)).cross(rb);
  return d_dot_d * (inv_mass_a + inv_mass_b) + d.dot(ang_a + ang_b);
}

// The same denominator from a constraint's rows, prepared once per step: r x n and I^-1 (r x n)
// for each body, so that n . [(I^-1 (r x n)) x r] is the dot product (r x n) . I^-1 (r x n). With
// the rows of two points i and j of one pair (one normal) it says how an impulse at j changes the
// normal velocity at i: the manifold's coupling matrix, whose diagonal is each point's own.
// `linear` is (1/m_a + 1/m_b) times n.n (1 for a unit n). Equal to inverse_effective_mass() but
// for rounding: the two sum in different orders, and each caller keeps the one its results were
// measured with.
inline Real inverse_effective_mass_of_rows(Real linear, const Vec3& ra_cross_n_i, const Vec3& angular_a_j,
                                           const Vec3& rb_cross_n_i, const Vec3& angular_b_j) {
  return linear + ra_cross_n_i.dot(angular_a_j) + rb_cross_n_i.dot(angular_b_j);
}

// The effective mass itself, 0 where nothing can move.
inline Real safe_inverse(Real k) { return k > 0 ? 1 / k : 0; }

// A point's separation now, from how far each body has moved and turned since the step began: its
// step-start separation along n (adjusted_separation = separation - (r_a - r_b) . n) plus the
// motion of its two anchors along n. n . (dq r) = (dq^-1 n) . r, so `normal_in_a` is n turned back
// by A's turn since the step began (n itself where turning does not move the point: a sphere's
// surface, a still body), and `moved_along_normal` is (dp_a - dp_b) . n. One pair (Real, Vec3), or
// two side by side (Real2, V3).
template <class R, class V>
[[gnu::always_inline]] inline R separation_now(R moved_along_normal, const V& normal_in_a, const V& normal_in_b, const V& anchor_a,
                                               const V& anchor_b, R adjusted_separation) {
  return moved_along_normal + dot(normal_in_a, anchor_a) - dot(normal_in_b, anchor_b) + adjusted_separation;
}

// The same for one point of two bodies' states; `turns_a`: whether A's turning carries the point.
inline Real separation_now(const Vec3& normal, const Vec3& anchor_a, const Vec3& anchor_b, Real adjusted_separation, const BodyState& sa,
                           bool turns_a, const BodyState& sb, bool turns_b) {
  const Vec3 normal_in_a = turns_a ? rotate(sa.dq.conjugate(), normal) : normal;
  const Vec3 normal_in_b = turns_b ? rotate(sb.dq.conjugate(), normal) : normal;
  return separation_now((sa.dp - sb.dp).dot(normal), normal_in_a, normal_in_b, anchor_a, anchor_b, adjusted_separation);
}

// The default method's normal row for one point, two pairs side by side (lanes.h): the new
// accumulated impulse from the accumulated one I and the normal velocity vn is
//   max(keep I - push - mass vn, 0)
// (eq. 13's J, clamped to push only), the row set once per sub-step by soft_normal_row(). The
// target is "stop approaching" with a soft position correction in the biased pass (Box2D v3's
// soft step: push = mass bias, keep = 1 - impulse_scale), without in the relax pass; a
// bounce's target is restitution's (contact_bounce.cpp).
struct NormalRow {
  Real2 mass, push, keep;
  Real2 bias;      // push / mass: the velocity the row drives vn towards -bias
  Mask2 touching;  // not apart: the row soft (biased solve) or rigid (relax)
};

// `separation` now; `normal_mass` 1 / eq. 13's denominator. A speculative point (apart) may close
// its gap this sub-step, no further; the relax pass leaves it be (mass 0): the next solve clamps
// it anyway, and slowing a body before it touches would lose the speed it hits with. Within
// kTouching the surfaces touch: a face that closed its gap would otherwise have some corners
// apart and others not, by rounding.
constexpr Real kTouching = 1e-6;  // m
template <bool UseBias>
[[gnu::always_inline]] inline NormalRow soft_normal_row(Real2 separation, Real2 normal_mass, const Softness& softness, Real inv_h,
                                                        Real2 max_push) {
  const Mask2 apart = separation > kTouching;
  if constexpr (UseBias) {
    const Real2 soft_bias = splat(softness.bias_rate) * separation;
    const Real2 bias = select(apart, separation * inv_h, select(soft_bias < max_push, max_push, soft_bias));
    const Real2 mass = select(apart, normal_mass, normal_mass * splat(softness.mass_scale));
    return {mass, mass * bias, select(apart, splat(1), splat(1 - softness.impulse_scale)), bias, ~apart};
  } else {
    return {select(apart, splat(0), normal_mass), splat(0), splat(1), splat(0), ~apart};
  }
}

// The row's new accumulated impulse, from the accumulated `impulse` and the normal velocity `vn`
// before this row's own change since then: pushing only.
[[gnu::always_inline]] inline Real2 clamped_normal_impulse(const NormalRow& row, Real2 impulse, Real2 vn) {
  return max0(row.keep * impulse - row.push - row.mass * vn);
}

}  // namespace impulse::physics
