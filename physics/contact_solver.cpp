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
  h_ = h;
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
    if (use_bias) c.approach_velocity = std::min(c.approach_velocity, touch_velocity(vn, separation, c.normal_acceleration, 1 / inv_h));
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

void ContactSolver::apply_restitution(std::vector<BodyState>& states) {
  for (ContactConstraint& c : constraints_) {
    if (c.restitution == 0 || c.approach_velocity > -settings_.restitution_threshold || c.max_normal_impulse == 0) continue;
    BodyState& sa = states[c.a];
    BodyState& sb = states[c.b];
    // eq. 5 and 13 with (1 + e): leave with e times the speed at which the bodies met.
    const Real vn = relative_velocity(sa, sb, c.anchor_a, c.anchor_b).dot(c.normal);
    // Clamped so that the step's impulse still only pushes; kept out of the warm-start value.
    // Leave at e times the touch speed (eq. 5), stored half a sub-step early as semi-implicit
    // Euler wants it, so that a ball dropped from H rises to e^2 H.
    const Real target = -c.restitution * c.approach_velocity - c.normal_acceleration * h_ / 2;
    const Real impulse = c.normal_mass * (target - vn);
    const Real applied = std::max(impulse, -c.normal_impulse);
    c.total_normal_impulse += applied;
    apply_impulse(sa, sb, c.anchor_a, c.anchor_b, applied * c.normal);
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
