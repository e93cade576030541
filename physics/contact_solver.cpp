#include "physics/contact_solver.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

Real mix_restitution(Real a, Real b) { return std::max(a, b); }
Real mix_friction(Real a, Real b) { return std::sqrt(a * b); }

namespace {

// Inverse of the effective mass along direction d at anchors ra, rb:
// 1/m_a + 1/m_b + d . [(I_a^-1 (r_a x d)) x r_a + (I_b^-1 (r_b x d)) x r_b]  (eq. 13's denominator)
Real inverse_effective_mass(const BodyState& sa, const BodyState& sb, const Vec3& ra, const Vec3& rb, const Vec3& d) {
  const Vec3 ang_a = (sa.inv_inertia * ra.cross(d)).cross(ra);
  const Vec3 ang_b = (sb.inv_inertia * rb.cross(d)).cross(rb);
  return sa.inv_mass + sb.inv_mass + d.dot(ang_a + ang_b);
}

Real safe_inverse(Real k) { return k > 0 ? 1 / k : 0; }

// The normal velocity at which the surfaces meet, predicted from a sub-step that starts
// `separation` apart with normal velocity `vn` (already including this sub-step's gravity) under
// relative acceleration `a` (v_touch^2 = v0^2 - 2 a s). Semi-implicit Euler's velocity leads by half a
// sub-step, hence v0 = vn - a h / 2. Returns 0 when they are not closing.
Real touch_velocity(Real vn, Real separation, Real a, Real h) {
  const Real v0 = vn - a * h / 2;
  if (separation <= 0) return std::min(v0, Real(0));
  const Real v_squared = v0 * v0 - 2 * a * separation;
  if (v_squared <= 0 || (v0 >= 0 && a >= 0)) return 0;
  return -std::sqrt(v_squared);
}

}  // namespace

void ContactSolver::prepare(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                            const std::vector<BodyState>& states, const ContactSolverSettings& settings,
                            const Vec3& gravity, Real h) {
  settings_ = settings;
  const Softness contact_soft = make_softness(settings.contact_hertz, settings.contact_damping_ratio, h);
  // Contacts against static bodies can be stiffer: only one body moves (Box2D's staticSoftness).
  const Softness static_soft = make_softness(2 * settings.contact_hertz, settings.contact_damping_ratio, h);
  constraints_.clear();
  constraints_.reserve(contacts.size());
  for (const Contact& contact : contacts) {
    const Body& body_a = bodies[contact.body_a];
    const Body& body_b = bodies[contact.body_b];
    const BodyState& sa = states[contact.body_a];
    const BodyState& sb = states[contact.body_b];
    ContactConstraint c;
    c.a = contact.body_a;
    c.b = contact.body_b;
    c.normal = contact.normal;
    tangent_basis(c.normal, c.tangent1, c.tangent2);
    c.anchor_a = contact.point - body_a.position;
    c.anchor_b = contact.point - body_b.position;
    c.adjusted_separation = contact.separation - (c.anchor_a - c.anchor_b).dot(c.normal);
    c.normal_mass = safe_inverse(inverse_effective_mass(sa, sb, c.anchor_a, c.anchor_b, c.normal));
    c.tangent_mass1 = safe_inverse(inverse_effective_mass(sa, sb, c.anchor_a, c.anchor_b, c.tangent1));
    c.tangent_mass2 = safe_inverse(inverse_effective_mass(sa, sb, c.anchor_a, c.anchor_b, c.tangent2));
    c.friction = settings.friction ? mix_friction(body_a.material.friction, body_b.material.friction) : 0;
    c.restitution = mix_restitution(body_a.material.restitution, body_b.material.restitution);
    c.softness = (sa.inv_mass == 0 || sb.inv_mass == 0) ? static_soft : contact_soft;
    c.normal_acceleration = ((sa.inv_mass > 0 ? gravity : Vec3::Zero()) - (sb.inv_mass > 0 ? gravity : Vec3::Zero())).dot(c.normal);
    constraints_.push_back(c);
  }
}

void ContactSolver::warm_start(std::vector<BodyState>& states) const {
  for (const ContactConstraint& c : constraints_) {
    const Vec3 impulse = c.normal_impulse * c.normal + c.tangent_impulse1 * c.tangent1 + c.tangent_impulse2 * c.tangent2;
    apply_impulse(states[c.a], states[c.b], c.anchor_a, c.anchor_b, impulse);
  }
}

void ContactSolver::solve(std::vector<BodyState>& states, Real inv_h, bool use_bias) {
  for (ContactConstraint& c : constraints_) {
    BodyState& sa = states[c.a];
    BodyState& sb = states[c.b];

    // Separation now, from how far each body has moved and turned since the step began.
    const Real separation = current_separation(c, sa, sb);

    Real bias = 0, mass_scale = 1, impulse_scale = 0;
    if (separation > 0) {
      // Speculative: may close the gap this sub-step, no further. The relax pass leaves it be:
      // the next solve clamps it anyway, and slowing a body before it touches would lose the
      // speed it hits with.
      if (!use_bias) continue;
      bias = separation * inv_h;
    } else if (use_bias) {
      bias = std::max(c.softness.bias_rate * separation, -settings_.max_push_velocity);
      mass_scale = c.softness.mass_scale;
      impulse_scale = c.softness.impulse_scale;
    }

    // Normal impulse (eq. 13 with 1+e folded into the restitution pass; here the target is
    // "stop approaching"), accumulated and clamped to push only.
    const Vec3 dv = relative_velocity(sa, sb, c.anchor_a, c.anchor_b);
    const Real vn = dv.dot(c.normal);
    if (use_bias && bounce(c, sa, sb, vn, separation, 1 / inv_h)) continue;
    Real impulse = -c.normal_mass * mass_scale * (vn + bias) - impulse_scale * c.normal_impulse;
    const Real new_impulse = std::max(c.normal_impulse + impulse, Real(0));
    impulse = new_impulse - c.normal_impulse;
    c.normal_impulse = new_impulse;
    c.max_normal_impulse = std::max(c.max_normal_impulse, impulse);
    apply_impulse(sa, sb, c.anchor_a, c.anchor_b, impulse * c.normal);

    // Coulomb friction on two tangents, clamped to the friction disc of radius mu * jn.
    if (c.friction > 0) {
      const Vec3 dvt = relative_velocity(sa, sb, c.anchor_a, c.anchor_b);
      const Real old1 = c.tangent_impulse1, old2 = c.tangent_impulse2;
      Real new1 = old1 - c.tangent_mass1 * dvt.dot(c.tangent1);
      Real new2 = old2 - c.tangent_mass2 * dvt.dot(c.tangent2);
      const Real limit = c.friction * c.normal_impulse;
      const Real length = std::hypot(new1, new2);
      if (length > limit) {
        const Real scale = limit / length;
        new1 *= scale;
        new2 *= scale;
      }
      c.tangent_impulse1 = new1;
      c.tangent_impulse2 = new2;
      apply_impulse(sa, sb, c.anchor_a, c.anchor_b, (new1 - old1) * c.tangent1 + (new2 - old2) * c.tangent2);
    }
  }
}

// A collision (restitution) is answered in the sub-step in which the surfaces meet, one contact at
// a time: so a hit passes along a row of touching bodies as in Newton's cradle, instead of being
// shared out inelastically first. Slower hits (resting contact) are left to the solver.
bool ContactSolver::bounce(ContactConstraint& c, BodyState& sa, BodyState& sb, Real vn, Real separation, Real h) {
  if (c.bounced || c.restitution == 0 || vn > -settings_.restitution_threshold) return false;
  if (separation + vn * h > 0) return false;  // will not meet within this sub-step

  // The hit acts at one world point for both bodies, midway between where their anchors are now,
  // so that it conserves angular momentum exactly; its effective mass follows.
  // (Offsets from the step-start contact point; r_a - r_b = x_b - x_a, and r = anchor at rest.)
  const Vec3 mean_motion = ((sa.dp + sa.dq * c.anchor_a) + (sb.dp + sb.dq * c.anchor_b)) / 2;
  const Vec3 half_span = (c.anchor_a - c.anchor_b) / 2;
  const Vec3 ra = mean_motion - sa.dp + half_span, rb = mean_motion - sb.dp - half_span;
  const Real normal_mass = safe_inverse(inverse_effective_mass(sa, sb, ra, rb, c.normal));
  vn = relative_velocity(sa, sb, ra, rb).dot(c.normal);

  // Exactly, under the constant relative acceleration a: the surfaces, `gap` apart at the start
  // of the sub-step, meet after tau at v_touch and part at u = -e v_touch (eq. 5). Semi-implicit
  // Euler's velocity lags its position by half a sub-step (its state (x, v) is the exact state
  // (x, v + a h/2)), so the velocity to store for the end of the sub-step is u + a (h/2 - tau).
  const Real a = c.normal_acceleration;
  const Real gap = std::max(separation, Real(0));
  const Real v_touch = touch_velocity(vn, gap, a, h);
  const Real v_start = vn - a * h / 2;
  const Real tau = gap > 0 ? 2 * gap / -(v_start + v_touch) : 0;
  const Real u = -c.restitution * v_touch;
  const Real target = u + a * (h / 2 - tau);
  const Real impulse = std::max(normal_mass * (target - vn), Real(0));  // eq. 13 with (1 + e)
  apply_impulse(sa, sb, ra, rb, impulse * c.normal);
  c.total_normal_impulse += impulse;
  c.max_normal_impulse = std::max(c.max_normal_impulse, impulse);
  c.bounced = true;

  // Friction during the hit, within the Coulomb disc of this impulse.
  if (c.friction > 0) {
    const Vec3 dvt = relative_velocity(sa, sb, ra, rb);
    Real j1 = -c.tangent_mass1 * dvt.dot(c.tangent1), j2 = -c.tangent_mass2 * dvt.dot(c.tangent2);
    const Real length = std::hypot(j1, j2), limit = c.friction * impulse;
    if (length > limit) {
      j1 *= limit / length;
      j2 *= limit / length;
    }
    apply_impulse(sa, sb, ra, rb, j1 * c.tangent1 + j2 * c.tangent2);
    c.total_tangent_impulse1 += j1;
    c.total_tangent_impulse2 += j2;
  }

  // Integrating the whole sub-step at `target` from `gap` would not leave the surfaces where the
  // exact motion does, u (h - tau) + a (h - tau)^2 / 2 apart: take the difference back afterwards.
  const Real after = h - tau;
  c.bounce_shift = (u * after + a * after * after / 2) - (gap + target * h);
  return true;
}

void ContactSolver::apply_bounce_shifts(std::vector<BodyState>& states) {
  for (ContactConstraint& c : constraints_) {
    if (c.bounce_shift == 0) continue;
    BodyState& sa = states[c.a];
    BodyState& sb = states[c.b];
    const Real total = sa.inv_mass + sb.inv_mass;
    if (total > 0) {
      sa.dp += c.normal * (c.bounce_shift * sa.inv_mass / total);
      sb.dp -= c.normal * (c.bounce_shift * sb.inv_mass / total);
    }
    c.bounce_shift = 0;
  }
}

void ContactSolver::end_substep() {
  for (ContactConstraint& c : constraints_) {
    c.total_normal_impulse += c.normal_impulse;
    c.total_tangent_impulse1 += c.tangent_impulse1;
    c.total_tangent_impulse2 += c.tangent_impulse2;
  }
}

}  // namespace impulse::physics
