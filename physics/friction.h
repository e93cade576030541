// Friction (exercise 1; ERRATA.md: the listing's is not clamped): Coulomb's law, |j_t| <= mu j_n,
// on two tangents at the centroid of a pair's points, within the disc of radius mu times their
// total normal impulse; a twist about the normal within mu j_n times the points' spread; and, for
// a sphere's one point, rolling resistance. The default method's rows run two pairs side by side
// (lanes.h); an impact solves one pair's rows exactly, and rolling resistance clamps one pair with
// the same function.
#pragma once
#include "physics/body_state.h"
#include "physics/contact_lanes.h"

namespace impulse::physics {

// The Coulomb clamp: friction impulses (j1, j2) on two tangents, scaled back onto the disc of
// radius `limit` where they fall outside it (no square root while they stick). For one pair (Real)
// or two side by side (Real2), lane by lane.
template <class R>
[[gnu::always_inline]] inline void clamp_to_coulomb_disc(R& j1, R& j2, R limit) {
  const R length_squared = j1 * j1 + j2 * j2;
  const auto outside = length_squared > limit * limit;
  if (!any(outside)) return;
  const R scale = select(outside, limit / sqrt(length_squared), R{} + 1);
  j1 = j1 * scale;
  j2 = j2 * scale;
}

// The friction rows of a block of two manifolds (va, wa, vb, wb: the bodies' velocities, lane by
// lane), given their points' total normal impulse: the accumulated impulses j1, j2 (and in the
// relax pass the twist) updated and the change applied to the velocities.
//
// Both passes hold the centroid's sliding velocity at zero with the full (hard) tangent mass:
// static friction has no position target, so a pair that rocks from a face onto an edge is not
// pulled back towards where it first touched (such a pull fed the rocking of resting heaps), and
// nothing leaks from the friction impulse in the biased pass (a soft friction let a heap slide
// apart at m/s). The twist is left to the relax pass: solved in the biased one too, a wall of
// boxes one box thick (the 21-box pyramid) swayed out of its plane.
template <bool UseBias>
[[gnu::always_inline]] inline void solve_friction_lanes(const ManifoldLanes& block, Real2 normal_sum, Real2 inv_mass_a, Real2 inv_mass_b,
                                                        V3& va, V3& wa, V3& vb, V3& wb, Real2& j1, Real2& j2, Real2& twist) {
  const Real2 limit = block.friction * normal_sum;
  const V3 dv = va - vb;
  const Real2 v1 = dot(dv, block.tangent1) + dot(wa, block.ra_cross_t1) - dot(wb, block.rb_cross_t1);
  const Real2 v2 = dot(dv, block.tangent2) + dot(wa, block.ra_cross_t2) - dot(wb, block.rb_cross_t2);
  const Real2 old1 = j1, old2 = j2, old_twist = twist;
  j1 = old1 - block.tangent_mass1 * v1;
  j2 = old2 - block.tangent_mass2 * v2;
  clamp_to_coulomb_disc(j1, j2, limit);
  if constexpr (!UseBias) {
    const Real2 twist_limit = limit * block.twist_radius;
    twist = select(block.twist_radius > 0, clamp(old_twist - block.twist_mass * dot(wa - wb, block.normal), -twist_limit, twist_limit),
                   old_twist);
  }
  // Not pressed together (a speculative pair): no friction.
  const Mask2 unpressed = limit == 0;
  j1 = select(unpressed, splat(0), j1);
  j2 = select(unpressed, splat(0), j2);
  twist = select(unpressed, splat(0), twist);
  const Real2 applied1 = j1 - old1, applied2 = j2 - old2, applied_twist = twist - old_twist;
  const V3 linear_friction = applied1 * block.tangent1 + applied2 * block.tangent2;
  va = va + inv_mass_a * linear_friction;
  wa = wa + (applied1 * block.turn_a1 + applied2 * block.turn_a2 + applied_twist * block.twist_a);
  vb = vb - inv_mass_b * linear_friction;
  wb = wb - (applied1 * block.turn_b1 + applied2 * block.turn_b2 + applied_twist * block.twist_b);
}

// Friction at an impact (contact_bounce.cpp), on lane l of the block of a manifold that bounced:
// its rows solved exactly by Coulomb's law with maximum dissipation. Of the friction impulses j
// within the disc |j| <= mu J (J: the bounce's normal impulse), the one that leaves the bodies the
// least kinetic energy: the impulse that stops the sliding where the surfaces meet when Coulomb
// allows it (sticking), else one on the disc's rim (sliding through the impact); for a sphere, mu J
// against the sliding, as Routh's analysis of the impact gives. Applied to the states, apart from
// the rows' accumulated impulses (the soft contact's, which the next sub-step warm starts).
// `impulse`, on the two tangents: the impact's so far (0 at first; again after the joints held
// have moved the bodies), changed to the new one.
void impact_friction(const ManifoldLanes& block, int l, Real bounce, Eigen::Matrix<Real, 2, 1>& impulse, BodyState& sa, BodyState& sb);

// impact_friction()'s kernel: the point of the disc |x| <= limit that minimises the kinetic energy
// left, (x - j0)^T K (x - j0) / 2 + (x - j0)^T v (K: the tangents' effective mass matrix, symmetric
// positive definite; v: the sliding velocity after j0).
Eigen::Matrix<Real, 2, 1> least_energy_in_disc(const Eigen::Matrix<Real, 2, 2>& k, const Eigen::Matrix<Real, 2, 1>& v,
                                               const Eigen::Matrix<Real, 2, 1>& j0, Real limit);

// Rolling resistance, in the relax pass, for a sphere's one point (the lanes `solved` whose
// rolling_radius is set): an angular impulse about the tangents against the bodies' relative
// turning, within the disc of radius c R N (a torque c R N over the sub-step: the rolling
// resistance coefficient c, as a rolling ball on a floor that gives a little meets, and so slows
// at c g / (1 + I / (m R^2))). Solved afresh each pass, not warm started: few manifolds have it,
// and each pass is one sub-step's worth.
void resist_rolling(const ManifoldLanes& block, Mask2 solved, Real2 normal_sum, const BodyState* const sa[2], const BodyState* const sb[2],
                    const std::vector<BodyInertia>& inertia, V3& wa, V3& wb);

}  // namespace impulse::physics
