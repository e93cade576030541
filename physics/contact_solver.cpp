#include "physics/contact_solver.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

Real mix_restitution(Real a, Real b) { return std::max(a, b); }
Real mix_friction(Real a, Real b) { return std::sqrt(a * b); }

namespace {

constexpr int kMaxManifoldPoints = 4;  // the collision routines reduce every pair to four

// Increasing with the pair, as the contacts come (ContactFinder), whichever body the narrow phase
// named first; and which one it was, in the lowest bit: a pair named the other way round has
// another normal and anchors, and is not warm started from this one.
uint64_t pair_key(int a, int b) {
  return (uint64_t(uint32_t(std::min(a, b))) << 33) | (uint64_t(uint32_t(std::max(a, b))) << 1) | uint64_t(a > b);
}

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

// Friction impulses j1, j2 clamped to the Coulomb disc of radius `limit`. Returns whether they
// asked for more than `slip` (the pair slides). No square root while they stick.
bool clamp_to_disc(Real& j1, Real& j2, Real limit, Real slip = INFINITY) {
  const Real length_squared = j1 * j1 + j2 * j2;
  if (length_squared <= limit * limit) return false;
  const Real scale = limit / std::sqrt(length_squared);
  j1 *= scale;
  j2 *= scale;
  return length_squared > slip * slip;
}

// A manifold point's normal row during one solve: its velocity along the normal now, its target
// (bias), soft mass and impulse.
struct NormalRow {
  PointRow* c;
  int point;
  Real vn, bias, mass, impulse_scale, impulse, start;
};

// One Gauss-Seidel pass over N rows that see each other through the coupling matrix, first to last
// or last to first. N and the direction are known to the compiler, so that the rows' velocities
// stay in registers: each row waits on the one before.
template <int N, bool Backwards>
void solve_rows(NormalRow* rows, const Real (&coupling)[4][4]) {
  Real vn[N], impulse[N], c[N][N];
  for (int i = 0; i < N; ++i) {
    vn[i] = rows[i].vn;
    impulse[i] = rows[i].impulse;
    for (int j = 0; j < N; ++j) c[i][j] = coupling[rows[i].point][rows[j].point];
  }
  for (int step = 0; step < N; ++step) {
    const int k = Backwards ? N - 1 - step : step;
    const NormalRow& row = rows[k];
    const Real new_impulse = std::max(impulse[k] - row.mass * (vn[k] + row.bias) - row.impulse_scale * impulse[k], Real(0));
    const Real applied = new_impulse - impulse[k];
    impulse[k] = new_impulse;
    for (int j = 0; j < N; ++j) vn[j] += c[j][k] * applied;
  }
  for (int i = 0; i < N; ++i) rows[i].impulse = impulse[i];
}

// One contact point's constraint, without its warm start.
ContactConstraint make_constraint(const Contact& contact, const std::vector<Body>& bodies, const std::vector<BodyState>& states,
                                  const std::vector<int>& slots, const ContactSolverSettings& settings, const Vec3& gravity,
                                  const Softness& contact_soft, const Softness& static_soft) {
  const Body& body_a = bodies[contact.body_a];
  const Body& body_b = bodies[contact.body_b];
  ContactConstraint c;
  c.a = slots[contact.body_a];
  c.b = slots[contact.body_b];
  c.feature = contact.feature;
  const BodyState& sa = states[c.a];
  const BodyState& sb = states[c.b];
  c.normal = contact.normal;
  tangent_basis(c.normal, c.tangent1, c.tangent2);
  c.anchor_a = contact.point - body_a.position;
  c.anchor_b = contact.point - body_b.position;
  c.adjusted_separation = contact.separation - (c.anchor_a - c.anchor_b).dot(c.normal);
  c.ra_cross_n = c.anchor_a.cross(c.normal);
  c.rb_cross_n = c.anchor_b.cross(c.normal);
  c.angular_a = sa.inv_inertia * c.ra_cross_n;
  c.angular_b = sb.inv_inertia * c.rb_cross_n;
  c.normal_mass = safe_inverse(sa.inv_mass + sb.inv_mass + c.ra_cross_n.dot(c.angular_a) + c.rb_cross_n.dot(c.angular_b));
  c.friction = settings.friction ? mix_friction(body_a.material.friction, body_b.material.friction) : 0;
  c.restitution = mix_restitution(body_a.material.restitution, body_b.material.restitution);
  c.softness = (sa.inv_mass == 0 || sb.inv_mass == 0) ? static_soft : contact_soft;
  c.normal_acceleration = ((sa.inv_mass > 0 ? gravity : Vec3::Zero()) - (sb.inv_mass > 0 ? gravity : Vec3::Zero())).dot(c.normal);
  return c;
}

}  // namespace

void ContactSolver::plan(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, ThreadTeam& team) {
  team_ = &team;
  // Consecutive contacts of one pair (with one normal) form its manifold, of at most four points.
  groups_.clear();
  for (int i = 0; i < int(contacts.size()); ++i) {
    const Contact& contact = contacts[i];
    if (groups_.empty() || groups_.back().second - groups_.back().first == kMaxManifoldPoints ||
        contacts[groups_.back().first].body_a != contact.body_a || contacts[groups_.back().first].body_b != contact.body_b ||
        contacts[groups_.back().first].normal != contact.normal)
      groups_.push_back({i, i});
    ++groups_.back().second;
  }
  auto moving = [&](int body) { return !bodies[body].is_static() && bodies[body].awake ? body : -1; };
  std::vector<SweepItem> items(groups_.size());
  for (size_t k = 0; k < groups_.size(); ++k) {
    const Contact& contact = contacts[groups_[k].first];
    items[k] = {moving(contact.body_a), moving(contact.body_b), bodies[contact.body_a].position, bodies[contact.body_b].position};
  }
  schedule_.plan(items, int(bodies.size()), team.size());
}

void ContactSolver::prepare(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                            const std::vector<BodyState>& states, const ContactSolverSettings& settings,
                            const Vec3& gravity, Real h) {
  settings_ = settings;
  const Real hertz = std::min(settings.contact_hertz, kMaxHertzPerSubstepRate / h);
  const Softness contact_soft = make_softness(hertz, settings.contact_damping_ratio, h);
  // Contacts against static bodies can be stiffer: only one body moves (Box2D's staticSoftness).
  const Softness static_soft = make_softness(2 * hertz, settings.contact_damping_ratio, h);
  // The constraints are laid out in the sweeps' order: a thread's share is then one block of memory.
  const std::vector<int>& slots = schedule_.slots();
  const std::vector<int>& order = schedule_.order();
  // Last step's constraints, if it stored its impulses, are the warm start: found by pair, then
  // by feature. Each thread reads what it built last step.
  if (impulses_stored_) {
    std::swap(previous_constraints_, constraints_);
    std::swap(previous_manifolds_, manifolds_);
    std::swap(previous_pairs_, pairs_);
  } else {
    previous_pairs_.clear();
  }
  impulses_stored_ = false;
  // Impulses are per sub-step: when the sub-step changes length, so do they.
  const Real warm_scale = stored_h_ > 0 ? h / stored_h_ : 1;
  h_ = h;
  manifolds_.resize(order.size());
  constraints_.resize(contacts.size());
  rows_.resize(contacts.size());
  constraint_of_contact_.resize(contacts.size());
  first_of_step_.resize(order.size());
  pairs_.resize(order.size());
  for (size_t step = 0, next = 0; step < order.size(); ++step) {
    const auto [first, end] = groups_[order[step]];
    first_of_step_[step] = int(next);
    for (int i = first; i < end; ++i) constraint_of_contact_[i] = int(next++);
    pairs_[order[step]] = {pair_key(contacts[first].body_a, contacts[first].body_b), int(step)};
  }
  find_previous_pairs();
  // Each thread builds the manifolds it sweeps, from the states and bodies it loaded.
  schedule_.run(*team_, [&](int thread) {
    schedule_.step_share(thread, [&](int step) {
      const auto [first, end] = groups_[order[step]];
      ManifoldConstraint& m = manifolds_[step];
      m = ManifoldConstraint{};
      m.a = slots[contacts[first].body_a];
      m.b = slots[contacts[first].body_b];
      m.first = first_of_step_[step];
      m.count = end - first;
      const auto [same_pair, other_pair] = previous_range_[order[step]];
      for (int i = 0; i < m.count; ++i) {
        ContactConstraint& c = constraints_[m.first + i];
        c = make_constraint(contacts[first + i], bodies, states, slots, settings, gravity, contact_soft, static_soft);
        for (int previous = same_pair; previous != other_pair; ++previous) {
          const ManifoldConstraint& pm = previous_manifolds_[previous_pairs_[previous].manifold];
          for (int j = 0; j < pm.count; ++j)
            if (previous_constraints_[pm.first + j].feature == c.feature) c.normal_impulse = warm_scale * previous_constraints_[pm.first + j].normal_impulse;
        }
      }
      prepare_manifold(m, bodies[contacts[first].body_a], bodies[contacts[first].body_b], states);
      for (int i = 0; i < m.count; ++i) {
        const ContactConstraint& c = constraints_[m.first + i];
        rows_[m.first + i] = {c.anchor_a, c.anchor_b, c.ra_cross_n, c.rb_cross_n, c.angular_a, c.angular_b,
                              c.adjusted_separation, c.normal_mass, c.normal_impulse, 0};
      }
      if (same_pair != other_pair) {
        warm_start_friction(m, previous_manifolds_[previous_pairs_[other_pair - 1].manifold], bodies[contacts[first].body_a], bodies[contacts[first].body_b]);
        m.tangent_impulse1 *= warm_scale;
        m.tangent_impulse2 *= warm_scale;
        m.twist_impulse *= warm_scale;
      }
    });
  });
}

// For each of this step's manifolds (in the contacts' order), the range of last step's with the
// same pair. Both lists come by pair, as the contacts do (ContactFinder): one merge, no search.
void ContactSolver::find_previous_pairs() {
  auto by_pair = [](const PairPlace& x, const PairPlace& y) { return x.key != y.key ? x.key < y.key : x.manifold < y.manifold; };
  if (!std::is_sorted(previous_pairs_.begin(), previous_pairs_.end(), by_pair)) std::sort(previous_pairs_.begin(), previous_pairs_.end(), by_pair);
  previous_range_.resize(pairs_.size());
  int begin = 0;
  const int count = int(previous_pairs_.size());
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const uint64_t key = pairs_[k].key;
    if (k > 0 && key < pairs_[k - 1].key)  // out of order after all: search from the start
      begin = int(std::lower_bound(previous_pairs_.begin(), previous_pairs_.end(), PairPlace{key, -1}, by_pair) - previous_pairs_.begin());
    while (begin < count && previous_pairs_[begin].key < key) ++begin;
    int end = begin;
    while (end < count && previous_pairs_[end].key == key) ++end;
    previous_range_[k] = {begin, end};
  }
}

// The friction rows of a manifold whose points are built.
void ContactSolver::prepare_manifold(ManifoldConstraint& m, const Body& body_a, const Body& body_b, const std::vector<BodyState>& states) const {
  const BodyState& sa = states[m.a];
  const BodyState& sb = states[m.b];
  const ContactConstraint& first = constraints_[m.first];
  m.normal = first.normal;
  m.tangent1 = first.tangent1;
  m.tangent2 = first.tangent2;
  m.softness = first.softness;
  m.friction = first.friction;
  m.restitution = first.restitution;
  Vec3 centre = Vec3::Zero();
  for (int i = 0; i < m.count; ++i) centre += constraints_[m.first + i].anchor_a;
  centre /= m.count;  // relative to A
  m.centre_a = centre;
  m.centre_b = centre + (first.anchor_b - first.anchor_a);
  m.tangent_mass1 = safe_inverse(inverse_effective_mass(sa, sb, m.centre_a, m.centre_b, first.tangent1));
  m.tangent_mass2 = safe_inverse(inverse_effective_mass(sa, sb, m.centre_a, m.centre_b, first.tangent2));
  // How an impulse at point j changes the normal velocity at point i (eq. 13's denominator,
  // generalised: its diagonal is the inverse of each point's normal mass).
  for (int i = 0; i < m.count; ++i)
    for (int j = 0; j < m.count; ++j) {
      const ContactConstraint& ci = constraints_[m.first + i];
      const ContactConstraint& cj = constraints_[m.first + j];
      m.coupling[i][j] = (sa.inv_mass + sb.inv_mass) * ci.normal.dot(cj.normal) + ci.ra_cross_n.dot(cj.angular_a) + ci.rb_cross_n.dot(cj.angular_b);
    }
  m.twist_mass = safe_inverse(first.normal.dot((sa.inv_inertia + sb.inv_inertia) * first.normal));
  m.ra_cross_t1 = m.centre_a.cross(first.tangent1);
  m.ra_cross_t2 = m.centre_a.cross(first.tangent2);
  m.rb_cross_t1 = m.centre_b.cross(first.tangent1);
  m.rb_cross_t2 = m.centre_b.cross(first.tangent2);
  m.turn_a1 = sa.inv_inertia * m.ra_cross_t1;
  m.turn_a2 = sa.inv_inertia * m.ra_cross_t2;
  m.turn_b1 = sb.inv_inertia * m.rb_cross_t1;
  m.turn_b2 = sb.inv_inertia * m.rb_cross_t2;
  m.twist_a = sa.inv_inertia * first.normal;
  m.twist_b = sb.inv_inertia * first.normal;
  m.twist_radius = 0;
  for (int i = 0; i < m.count; ++i) m.twist_radius += (constraints_[m.first + i].anchor_a - centre).norm() / m.count;
  m.local_anchor_a = body_a.orientation.conjugate() * m.centre_a;
  m.local_anchor_b = body_b.orientation.conjugate() * m.centre_b;
  // A sphere's surface stays where it is as it turns, and a still body does not turn.
  m.turns_a = sa.inv_mass > 0 && body_a.shape.type != ShapeType::sphere;
  m.turns_b = sb.inv_mass > 0 && body_b.shape.type != ShapeType::sphere;
}

// Last step's friction impulses, and its anchor unless the pair slipped.
void ContactSolver::warm_start_friction(ManifoldConstraint& m, const ManifoldConstraint& previous, const Body& body_a, const Body& body_b) const {
  m.tangent_impulse1 = previous.tangent_impulse1;
  m.tangent_impulse2 = previous.tangent_impulse2;
  m.twist_impulse = previous.twist_impulse;
  if (previous.slipped) return;  // a pair that slipped is anchored afresh where it touches now
  m.local_anchor_a = previous.local_anchor_a;
  m.local_anchor_b = previous.local_anchor_b;
  const Vec3 offset = (body_a.position + body_a.orientation * m.local_anchor_a) - (body_b.position + body_b.orientation * m.local_anchor_b);
  const Vec3& normal = m.normal;
  m.drift = offset - offset.dot(normal) * normal;
}

void ContactSolver::warm_start(std::vector<BodyState>& states) {
  schedule_.sweep(*team_, [&](int index) { warm_start_manifold(index, states); });
}

void ContactSolver::solve(std::vector<BodyState>& states, Real inv_h, bool use_bias) {
  schedule_.sweep(*team_, [&](int index) { solve_manifold(index, states, inv_h, use_bias); });
}

void ContactSolver::apply_bounce_shifts(std::vector<BodyState>& states) {
  schedule_.sweep(*team_, [&](int index) { shift_bounce(index, states); });
}

void ContactSolver::end_substep() {
  schedule_.for_each_step(*team_, [&](int index) { add_to_totals(index); });
  backwards_ = !backwards_;
}

void ContactSolver::warm_start_manifold(int index, std::vector<BodyState>& states) const {
  const ManifoldConstraint& m = manifolds_[index];
  BodyState& sa = states[m.a];
  BodyState& sb = states[m.b];
  // The points share the normal: one sum of their impulses, added to each body once with friction's.
  Real normal_sum = 0;
  Vec3 turn_a = m.tangent_impulse1 * m.turn_a1 + m.tangent_impulse2 * m.turn_a2 + m.twist_impulse * m.twist_a;
  Vec3 turn_b = m.tangent_impulse1 * m.turn_b1 + m.tangent_impulse2 * m.turn_b2 + m.twist_impulse * m.twist_b;
  for (int i = 0; i < m.count; ++i) {
    const PointRow& c = rows_[m.first + i];
    normal_sum += c.normal_impulse;
    turn_a += c.normal_impulse * c.angular_a;
    turn_b += c.normal_impulse * c.angular_b;
  }
  const Vec3 linear = normal_sum * m.normal + m.tangent_impulse1 * m.tangent1 + m.tangent_impulse2 * m.tangent2;
  add_velocity(sa, sa.inv_mass * linear, turn_a);
  add_velocity(sb, -(sb.inv_mass * linear), -turn_b);
}

bool ContactSolver::solve_manifold(int index, std::vector<BodyState>& states, Real inv_h, bool use_bias) {
  ManifoldConstraint& m = manifolds_[index];
  BodyState& sa = states[m.a];
  BodyState& sb = states[m.b];
  if (use_bias && bounce(m, sa, sb, 1 / inv_h)) return true;
  solve_normals(m, states, inv_h, use_bias);
  if (m.friction == 0) return false;
  Real normal_sum = 0;
  for (int i = 0; i < m.count; ++i) normal_sum += rows_[m.first + i].normal_impulse;
  solve_friction(m, sa, sb, normal_sum, use_bias);
  return false;
}

void ContactSolver::solve_normals(ManifoldConstraint& m, std::vector<BodyState>& states, Real inv_h, bool use_bias) {
  BodyState& sa = states[m.a];
  BodyState& sb = states[m.b];
  const Vec3 dv = sa.v - sb.v;
  // The points share the normal: n . (dq r) = (dq^-1 n) . r turns the normal back once per body
  // instead of turning every anchor (current_separation, for the manifold).
  const Vec3& normal = m.normal;
  const Real moved = (sa.dp - sb.dp).dot(normal);
  const Vec3 normal_in_a = m.turns_a ? rotate(sa.dq.conjugate(), normal) : normal;
  const Vec3 normal_in_b = m.turns_b ? rotate(sb.dq.conjugate(), normal) : normal;
  // Each point's target, from its separation now (positions do not change during the passes),
  // and its normal velocity now.
  NormalRow rows[kMaxManifoldPoints];
  int row_count = 0;
  for (int i = 0; i < m.count; ++i) {
    PointRow& c = rows_[m.first + i];
    const Real separation = moved + normal_in_a.dot(c.anchor_a) - normal_in_b.dot(c.anchor_b) + c.adjusted_separation;
    const Real vn = dv.dot(normal) + sa.w.dot(c.ra_cross_n) - sb.w.dot(c.rb_cross_n);
    NormalRow row{&c, i, vn, 0, c.normal_mass, 0, c.normal_impulse, c.normal_impulse};
    if (separation > 0) {
      // Speculative: may close the gap this sub-step, no further. The relax pass leaves it be:
      // the next solve clamps it anyway, and slowing a body before it touches would lose the
      // speed it hits with.
      if (!use_bias) continue;
      row.bias = separation * inv_h;
    } else if (use_bias) {
      row.bias = std::max(m.softness.bias_rate * separation, -settings_.max_push_velocity);
      row.mass *= m.softness.mass_scale;
      row.impulse_scale = m.softness.impulse_scale;
    }
    rows[row_count++] = row;
  }

  // Accumulated and clamped to push only; the target is "stop approaching" (restitution is
  // bounce()'s). Gauss-Seidel point after point, as if each impulse were applied to the bodies at
  // once; but the points of one pair see each other only through the coupling matrix, so the pass
  // updates their normal velocities alone, and the bodies get the sum afterwards (the same
  // arithmetic, without a chain through the bodies' velocities after every point). One pass, in
  // turn forwards and backwards from one sub-step to the next: always forwards, the first point
  // gets more than its share, and a wall of boxes one box thick (the 21-box pyramid) starts to
  // sway; two passes forwards also hold, at 8 % more time on the 210 pyramid.
  switch (row_count * 2 + backwards_) {
    case 2: solve_rows<1, false>(rows, m.coupling); break;
    case 3: solve_rows<1, true>(rows, m.coupling); break;
    case 4: solve_rows<2, false>(rows, m.coupling); break;
    case 5: solve_rows<2, true>(rows, m.coupling); break;
    case 6: solve_rows<3, false>(rows, m.coupling); break;
    case 7: solve_rows<3, true>(rows, m.coupling); break;
    case 8: solve_rows<4, false>(rows, m.coupling); break;
    case 9: solve_rows<4, true>(rows, m.coupling); break;
    default: break;
  }
  Vec3 linear = Vec3::Zero(), turn_a = Vec3::Zero(), turn_b = Vec3::Zero();
  for (int k = 0; k < row_count; ++k) {
    PointRow& c = *rows[k].c;
    const Real applied = rows[k].impulse - rows[k].start;
    c.normal_impulse = rows[k].impulse;
    linear += applied * normal;
    turn_a += applied * c.angular_a;
    turn_b += applied * c.angular_b;
  }
  add_velocity(sa, sa.inv_mass * linear, turn_a);
  add_velocity(sb, -(sb.inv_mass * linear), -turn_b);
}

// Tangent impulses j1, j2 at the points' centroid and a twist about the normal: +j on A, -j on B.
void ContactSolver::apply_friction(const ManifoldConstraint& m, BodyState& sa, BodyState& sb, Real j1, Real j2, Real twist) const {
  const Vec3 linear = j1 * m.tangent1 + j2 * m.tangent2;
  add_velocity(sa, sa.inv_mass * linear, j1 * m.turn_a1 + j2 * m.turn_a2 + twist * m.twist_a);
  add_velocity(sb, -(sb.inv_mass * linear), -(j1 * m.turn_b1 + j2 * m.turn_b2 + twist * m.twist_b));
}

// Coulomb friction at the points' centroid, within the disc of radius mu times their total
// normal impulse, and a twist about the normal within mu times that times the points' spread.
void ContactSolver::solve_friction(ManifoldConstraint& m, BodyState& sa, BodyState& sb, Real normal_sum, bool use_bias) {
  const Real limit = m.friction * normal_sum;
  if (limit == 0) {
    // Not pressed together (a speculative pair): no friction, and nothing to anchor.
    m.slipped = true;
    if (m.tangent_impulse1 == 0 && m.tangent_impulse2 == 0 && m.twist_impulse == 0) return;
    apply_friction(m, sa, sb, -m.tangent_impulse1, -m.tangent_impulse2, -m.twist_impulse);
    m.tangent_impulse1 = m.tangent_impulse2 = m.twist_impulse = 0;
    return;
  }
  const Vec3 dv = sa.v - sb.v;
  Real v1 = dv.dot(m.tangent1) + sa.w.dot(m.ra_cross_t1) - sb.w.dot(m.rb_cross_t1);
  Real v2 = dv.dot(m.tangent2) + sa.w.dot(m.ra_cross_t2) - sb.w.dot(m.rb_cross_t2);
  // Static friction also undoes the drift from where the pair first touched, softly, as the
  // normal rows undo penetration; without it tiny slips add up and stacks creep.
  Real mass_scale = 1, impulse_scale = 0;
  if (use_bias) {
    const Vec3 centre_a_now = sa.inv_mass > 0 ? rotate(sa.dq, m.centre_a) : m.centre_a;  // a still body has not turned
    const Vec3 centre_b_now = sb.inv_mass > 0 ? rotate(sb.dq, m.centre_b) : m.centre_b;
    const Vec3 moved = (sa.dp - sb.dp) + (centre_a_now - centre_b_now) - (m.centre_a - m.centre_b);
    const Vec3 drift = m.softness.bias_rate * (m.drift + moved);
    v1 += drift.dot(m.tangent1);
    v2 += drift.dot(m.tangent2);
    mass_scale = m.softness.mass_scale;
    impulse_scale = m.softness.impulse_scale;
  }
  const Real old1 = m.tangent_impulse1, old2 = m.tangent_impulse2;
  m.tangent_impulse1 += -m.tangent_mass1 * mass_scale * v1 - impulse_scale * old1;
  m.tangent_impulse2 += -m.tangent_mass2 * mass_scale * v2 - impulse_scale * old2;
  if (clamp_to_disc(m.tangent_impulse1, m.tangent_impulse2, limit, 1.0001 * limit + 1e-12)) m.slipped = true;

  Real twist = 0;
  if (m.twist_radius > 0) {
    const Real old_twist = m.twist_impulse;
    const Real twist_limit = limit * m.twist_radius;
    m.twist_impulse = std::clamp(old_twist - m.twist_mass * (sa.w - sb.w).dot(m.normal), -twist_limit, twist_limit);
    twist = m.twist_impulse - old_twist;
  }
  apply_friction(m, sa, sb, m.tangent_impulse1 - old1, m.tangent_impulse2 - old2, twist);
}

// A collision (restitution) is answered in the sub-step in which the surfaces meet, one pair at a
// time: so a hit passes along a row of touching bodies as in Newton's cradle, instead of being
// shared out inelastically first. Slower hits (resting contact) are left to the solver.
bool ContactSolver::bounce(ManifoldConstraint& m, BodyState& sa, BodyState& sb, Real h) {
  if (m.bounced || m.restitution == 0) return false;
  // Cheap first: is any point closing fast enough to bounce at all?
  bool closing = false;
  for (int i = 0; i < m.count && !closing; ++i) {
    const PointRow& c = rows_[m.first + i];
    closing = (sa.v - sb.v).dot(m.normal) + sa.w.dot(c.ra_cross_n) - sb.w.dot(c.rb_cross_n) < -settings_.restitution_threshold;
  }
  if (!closing) return false;

  // The points that meet within this sub-step, fast enough to bounce.
  struct Hit { int index; Vec3 ra, rb; Real normal_mass, target, u, tau, gap, impulse; };
  Hit hits[8];
  int hit_count = 0;
  for (int i = 0; i < m.count && hit_count < 8; ++i) {
    const ContactConstraint& c = constraints_[m.first + i];
    const Real separation = current_separation(c, sa, sb);
    const Real vn = relative_velocity(sa, sb, c.anchor_a, c.anchor_b).dot(c.normal);
    if (vn > -settings_.restitution_threshold || separation + vn * h > 0) continue;

    Hit& hit = hits[hit_count++];
    hit.index = m.first + i;
    // The hit acts at one world point for both bodies, midway between where their anchors are
    // now, so that it conserves angular momentum exactly (r_a - r_b = x_b - x_a).
    const Vec3 mean_motion = ((sa.dp + rotate(sa.dq, c.anchor_a)) + (sb.dp + rotate(sb.dq, c.anchor_b))) / 2;
    const Vec3 half_span = (c.anchor_a - c.anchor_b) / 2;
    hit.ra = mean_motion - sa.dp + half_span;
    hit.rb = mean_motion - sb.dp - half_span;
    hit.normal_mass = safe_inverse(inverse_effective_mass(sa, sb, hit.ra, hit.rb, c.normal));
    // Exactly, under the constant relative acceleration a: the surfaces, `gap` apart at the start
    // of the sub-step, meet after tau at v_touch and part at u = -e v_touch (eq. 5). Semi-implicit
    // Euler's velocity lags its position by half a sub-step (its state (x, v) is the exact state
    // (x, v + a h/2)), so the velocity to aim for at the end of the sub-step is u + a (h/2 - tau).
    const Real a = c.normal_acceleration;
    const Real vn_mid = relative_velocity(sa, sb, hit.ra, hit.rb).dot(c.normal);
    hit.gap = std::max(separation, Real(0));
    const Real v_touch = touch_velocity(vn_mid, hit.gap, a, h);
    const Real v_start = vn_mid - a * h / 2;
    hit.tau = hit.gap > 0 ? 2 * hit.gap / -(v_start + v_touch) : 0;
    hit.u = -c.restitution * v_touch;
    hit.target = hit.u + a * (h / 2 - hit.tau);
    hit.impulse = 0;
  }
  if (hit_count == 0) return false;

  // The points of one face land together: iterate them to agreement (eq. 13 with 1 + e, each
  // accumulated and clamped to push only).
  for (int iteration = 0; iteration < (hit_count == 1 ? 1 : 8); ++iteration) {
    for (int k = 0; k < hit_count; ++k) {
      Hit& hit = hits[k];
      const Vec3& normal = m.normal;
      const Real vn = relative_velocity(sa, sb, hit.ra, hit.rb).dot(normal);
      const Real new_impulse = std::max(hit.impulse + hit.normal_mass * (hit.target - vn), Real(0));
      apply_impulse(sa, sb, hit.ra, hit.rb, (new_impulse - hit.impulse) * normal);
      hit.impulse = new_impulse;
    }
  }

  // Friction during the hit, at the hit points' centroid, within mu times the hit's impulse.
  Real impulse_sum = 0;
  Vec3 ra = Vec3::Zero(), rb = Vec3::Zero();
  for (int k = 0; k < hit_count; ++k) {
    rows_[hits[k].index].total_normal_impulse += hits[k].impulse;
    impulse_sum += hits[k].impulse;
    ra += hits[k].ra / hit_count;
    rb += hits[k].rb / hit_count;
  }
  if (m.friction > 0 && impulse_sum > 0) {
    const Vec3 dv = relative_velocity(sa, sb, ra, rb);
    Real j1 = -safe_inverse(inverse_effective_mass(sa, sb, ra, rb, m.tangent1)) * dv.dot(m.tangent1);
    Real j2 = -safe_inverse(inverse_effective_mass(sa, sb, ra, rb, m.tangent2)) * dv.dot(m.tangent2);
    clamp_to_disc(j1, j2, m.friction * impulse_sum);
    apply_impulse(sa, sb, ra, rb, j1 * m.tangent1 + j2 * m.tangent2);
    m.total_tangent_impulse1 += j1;
    m.total_tangent_impulse2 += j2;
  }

  // Integrating the whole sub-step at `target` from `gap` would not leave the surfaces where the
  // exact motion does, u (h - tau) + a (h - tau)^2 / 2 apart: take the difference back afterwards,
  // for the point that met first.
  const Hit* earliest = std::min_element(hits, hits + hit_count, [](const Hit& x, const Hit& y) { return x.tau < y.tau; });
  const Real a = constraints_[earliest->index].normal_acceleration, after = h - earliest->tau;
  m.bounce_shift = (earliest->u * after + a * after * after / 2) - (earliest->gap + earliest->target * h);
  m.bounce_speed = earliest->u;
  m.bounced = true;
  return true;
}

// The shift is taken back as a time shift of the pair: each body moves along its own velocity for
// the same dt. That changes neither momentum nor angular momentum (sum of v dt x m v = 0).
void ContactSolver::shift_bounce(int index, std::vector<BodyState>& states) {
  ManifoldConstraint& m = manifolds_[index];
  if (m.bounce_shift == 0) return;
  BodyState& sa = states[m.a];
  BodyState& sb = states[m.b];
  const Real parting = (sa.v - sb.v).dot(m.normal);
  // Only while the pair parts at no less than half its bounce: one that barely parts (the bodies
  // around took the hit up) would be shifted by seconds of its velocity. Measured in a heap of
  // 1000 boxes with e = 0.5, before this rule: a shift of -162 s, a box thrown out at 159 m/s.
  if (parting > 1e-6 && parting >= m.bounce_speed / 2) {
    const Real dt = m.bounce_shift / parting;
    if (sa.inv_mass > 0) sa.dp += sa.v * dt;
    if (sb.inv_mass > 0) sb.dp += sb.v * dt;
  }
  m.bounce_shift = 0;
}

void ContactSolver::add_to_totals(int index) {
  ManifoldConstraint& m = manifolds_[index];
  for (int i = 0; i < m.count; ++i) rows_[m.first + i].total_normal_impulse += rows_[m.first + i].normal_impulse;
  m.total_tangent_impulse1 += m.tangent_impulse1;
  m.total_tangent_impulse2 += m.tangent_impulse2;
}

void ContactSolver::store_impulses() {
  impulses_stored_ = true;
  stored_h_ = h_;
  loads_.resize(manifolds_.size());
  schedule_.for_each_step(*team_, [&](int index) {
    const ManifoldConstraint& m = manifolds_[index];
    for (int i = 0; i < m.count; ++i) {  // for the records and the next step's warm start
      constraints_[m.first + i].normal_impulse = rows_[m.first + i].normal_impulse;
      constraints_[m.first + i].total_normal_impulse = rows_[m.first + i].total_normal_impulse;
    }
    ManifoldLoad& load = loads_[index];
    load = {m.a, m.b, 0, 0, constraints_[m.first].normal};
    for (int i = 0; i < m.count; ++i) {
      load.impulse += constraints_[m.first + i].normal_impulse;
      load.normal_mass += constraints_[m.first + i].normal_mass;
    }
    // For the records: each point's share of the friction, by its share of the normal impulse.
    Real normal_sum = 0;
    for (int i = 0; i < m.count; ++i) normal_sum += constraints_[m.first + i].total_normal_impulse;
    for (int i = 0; i < m.count; ++i) {
      ContactConstraint& c = constraints_[m.first + i];
      const Real share = normal_sum > 0 ? c.total_normal_impulse / normal_sum : Real(1) / m.count;
      c.total_tangent_impulse1 = share * m.total_tangent_impulse1;
      c.total_tangent_impulse2 = share * m.total_tangent_impulse2;
    }
  });
}

}  // namespace impulse::physics
