// How the default method's sweeps run: two manifolds side by side, one in each lane of an SSE
// register (lanes.h; Box2D v3 solves four or eight wide the same way). The maths is the
// equations' (normal_impulse.h, friction.h); this is its data, packed lane by lane by prepare()
// from the manifolds and their points, and copied back by store_impulses(). Each field holds the
// first manifold's value in lane 0 and the second's in lane 1; a manifold solved alone leaves
// lane 1 empty (the world's still slot: no mass, no friction).
#pragma once
#include "physics/lanes.h"
#include "physics/pair_points.h"

namespace impulse::physics {

struct PointLanes {
  V3 anchor_a, anchor_b, ra_cross_n, rb_cross_n, angular_a, angular_b;
  Real2 adjusted_separation, normal_mass;
  Real2 normal_impulse, total_normal_impulse;
};

struct alignas(64) ManifoldLanes {
  int a[2], b[2];                  // slots
  int points = 0;                  // each manifold's
  int first_point = 0;             // in the solver's PointLanes
  bool can_bounce = false;         // either has restitution
  V3 normal, tangent1, tangent2;
  Real2 friction;
  Real2 turns_a, turns_b;          // 1 where the body's turning moves the points along the normal
  Real2 face_of;                   // 1 where the normal is A's face's, 2 where B's (it turns with that body), else 0
  V3 centres;                      // anchor_a - anchor_b: B's centre less A's at the step's start
  Real2 coupling[4][4];            // d(normal velocity at i) / d(impulse at j), for the points
  PairFactors factors[2];          // the factor each solve last used (pair_points.h): the relax solve's [0], the biased solve's [1]
  Real2 tangent_mass1, tangent_mass2, twist_mass;
  Real2 twist_radius;              // mean distance of the points from their centroid
  Real2 rolling_radius;            // rolling resistance times the spheres' radius, else 0
  // The friction rows' angular parts, fixed for the step: r x t at the points' centroid, and how
  // an impulse along t1, t2 or a twist about n turns each body (I^-1 (r x t), I^-1 n).
  V3 ra_cross_t1, ra_cross_t2, rb_cross_t1, rb_cross_t2;
  V3 turn_a1, turn_a2, turn_b1, turn_b2, twist_a, twist_b;
  Real2 tangent_impulse1, tangent_impulse2, twist_impulse;
  Real2 total_tangent_impulse1, total_tangent_impulse2;
};

// A manifold's geometry, from which set_rows() writes the rows one lane is solved with: at the
// step's start (prepare()) or at the moment of contact (a bounce). The points' lever arms from
// each centre, the friction rows' (at the points' centroid, or at a bounce's hits'), the bodies'
// inverse masses and world inverse inertias.
struct RowGeometry {
  Vec3 normal, tangent1, tangent2;
  int count = 0;
  const Vec3* ra = nullptr;
  const Vec3* rb = nullptr;
  Vec3 centre_a, centre_b;
  Real inv_mass_a = 0, inv_mass_b = 0;
  const Mat3* inv_inertia_a = nullptr;
  const Mat3* inv_inertia_b = nullptr;
};
// Each point's normal row (r x n, I^-1 (r x n), 1 / eq. 13's denominator), their coupling, and the
// friction and twist rows, in lane l of `block` and its `points`. With `soft_share` (the biased
// solve's rows' compliance share), the two solves' factors for every point touching too
// (pair_points.h); without, the lane is left with none.
void set_rows(ManifoldLanes& block, PointLanes* points, int l, const RowGeometry& g, const Real* soft_share = nullptr);
// The friction and twist rows alone.
void set_friction_rows(ManifoldLanes& block, int l, const RowGeometry& g);

}  // namespace impulse::physics
