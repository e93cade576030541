#include "physics/restitution.h"

#include "physics/manifold.h"
#include "physics/normal_impulse.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

namespace {

// The normal velocity at which the surfaces meet, from a sub-step that starts `separation` apart
// with normal velocity `vn` (this sub-step's gravity included) under relative acceleration `a`
// (v_touch^2 = v0^2 - 2 a s, v0 = vn - a h / 2: Hit's half sub-step). 0 when they do not close.
Real touch_velocity(Real vn, Real separation, Real a, Real h) {
  const Real v0 = vn - a * h / 2;
  if (separation <= 0) return std::min(v0, Real(0));
  const Real v_squared = v0 * v0 - 2 * a * separation;
  if (v_squared <= 0 || (v0 >= 0 && a >= 0)) return 0;
  return -std::sqrt(v_squared);
}

// A's share of carrying a point: 1 when the point is A's (a sphere's surface, A's corner), 0 when
// B's, 1/2 when both make it. A still body carries nothing: the moving one slides over it.
Real share_of_a(const ManifoldConstraint& m, uint32_t feature, const BodyState& sa, const BodyState& sb) {
  if (m.radius_a > 0) return 1;
  if (m.radius_b > 0) return 0;
  if (sb.inv_mass == 0) return 1;
  if (sa.inv_mass == 0) return 0;
  const int corner_of = feature::corner_of(feature);
  return corner_of < 0 ? Real(0.5) : Real(corner_of == 0);
}

// I^-1 of a body turned by dq since the step began: R I0^-1 R^T.
Mat3 turned_inverse_inertia(const Mat3& inv_inertia, const Quat& dq) {
  const Mat3 r = dq.toRotationMatrix();
  return r * inv_inertia * r.transpose();
}

// x_a - x_b now plus `tau` of their velocities: at the step's start anchor_b - anchor_a (the
// anchors of one world point).
Vec3 centres_apart(const ContactAnchors& c, const BodyState& sa, const BodyState& sb, Real tau) {
  return (c.anchor_b - c.anchor_a) + (sa.dp + sa.v * tau) - (sb.dp + sb.v * tau);
}

}  // namespace

bool meets(Real separation, Real vn, Real a, Real restitution, Real threshold, Real h, Hit& hit) {
  // Within kTouching at the sub-step's end the surfaces touch (the relax pass's rows would stop
  // them there): they meet in this sub-step, at its end at the latest.
  if (vn > -threshold || separation + vn * h > kTouching) return false;
  hit.gap = std::max(separation, Real(0));
  hit.touch = touch_velocity(vn, hit.gap, a, h);
  if (hit.touch >= 0) return false;
  const Real v_start = vn - a * h / 2;
  hit.tau = hit.gap > 0 ? std::min(2 * hit.gap / -(v_start + hit.touch), h) : 0;
  hit.u = -restitution * hit.touch;
  hit.target = hit.u + a * (h / 2 - hit.tau);
  return true;
}

bool meets_at(Real separation, Real vn, Real a, Real restitution, Real threshold, Real h, Real tau, Hit& hit) {
  if (vn > -threshold) return false;
  hit.gap = std::max(separation, Real(0));
  hit.touch = touch_velocity(vn, hit.gap, a, h);
  if (hit.touch >= 0) return false;
  hit.tau = tau;
  hit.u = -restitution * hit.touch;
  hit.target = hit.u + a * (h / 2 - hit.tau);
  return true;
}

ImpactGeometry impact_geometry(const ManifoldConstraint& m, const ContactAnchors* points, const BodyState& sa, const BodyInertia& ia,
                               const BodyState& sb, const BodyInertia& ib, Real tau) {
  ImpactGeometry g;
  g.count = m.count;
  g.normal = m.normal;
  // A round side's point stays put as its body turns (turns_a false), but its inertia turns.
  const bool inertia_turns_a = sa.inv_mass > 0 && m.radius_a == 0, inertia_turns_b = sb.inv_mass > 0 && m.radius_b == 0;
  Quat dq_a = sa.dq, dq_b = sb.dq;
  if (inertia_turns_a) turn(dq_a, sa.w, tau);
  if (inertia_turns_b) turn(dq_b, sb.w, tau);
  g.inv_inertia_a = inertia_turns_a ? turned_inverse_inertia(ia.inv_inertia, dq_a) : ia.inv_inertia;
  g.inv_inertia_b = inertia_turns_b ? turned_inverse_inertia(ib.inv_inertia, dq_b) : ib.inv_inertia;
  g.moved_a = sa.dp + sa.v * tau;
  const Vec3 d = centres_apart(points[0], sa, sb, tau);
  if (m.radius_a > 0 && m.radius_b > 0) {  // two spheres: on the line of centres
    const Real distance = d.norm();
    if (distance > Real(1e-12)) g.normal = d / distance;
    for (int i = 0; i < m.count; ++i) {
      g.ra[i] = -m.radius_a * g.normal;
      g.rb[i] = g.ra[i] + d;
    }
    return g;
  }
  for (int i = 0; i < m.count; ++i) {
    const ContactAnchors& c = points[i];
    // Each body's surface point at the step's start: the contact point lies midway between them.
    const Real separation = c.adjusted_separation + (c.anchor_a - c.anchor_b).dot(m.normal);
    Vec3 on_a = m.radius_a > 0 ? Vec3(-m.radius_a * m.normal) : Vec3(c.anchor_a + m.normal * (separation / 2));
    Vec3 on_b = m.radius_b > 0 ? Vec3(m.radius_b * m.normal) : Vec3(c.anchor_b - m.normal * (separation / 2));
    if (m.turns_a) on_a = rotate(dq_a, on_a);
    if (m.turns_b) on_b = rotate(dq_b, on_b);
    const Real share = share_of_a(m, c.feature, sa, sb);
    g.ra[i] = share * on_a + (1 - share) * (on_b - d);
    g.rb[i] = g.ra[i] + d;
  }
  return g;
}

Real impact_separation(const ManifoldConstraint& m, const ContactAnchors& c, const BodyState& sa, const BodyState& sb) {
  if (m.radius_a > 0 && m.radius_b > 0) return centres_apart(c, sa, sb, 0).norm() - m.radius_a - m.radius_b;
  return separation_now(m.normal, c.anchor_a, c.anchor_b, c.adjusted_separation, sa, m.turns_a, sb, m.turns_b);
}

void advance(BodyState& s, Real t) {
  if (s.inv_mass == 0 || t == 0) return;
  s.dp += s.v * t;
  turn(s.dq, s.w, t);
}

}  // namespace impulse::physics
