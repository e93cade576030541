// Preparing the default method's contacts and warm starting them: the manifolds planned for the
// sweeps, each point's constraint (its rows of eq. 13), each manifold's shared rows (the points'
// coupling, friction at their centroid), last step's impulses found again by pair and feature, all
// packed for the sweeps; and at the end of the step the impulses kept for the next.
#include "physics/contact_solver.h"
#include "physics/manifold.h"
#include "physics/normal_impulse.h"
#include "physics/restitution.h"
#include "physics/step_buffer.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

namespace {

// Increasing with the pair, as the contacts come (ContactFinder), whichever body the narrow phase
// named first; and which one it was, in the lowest bit: a pair named the other way round has
// another normal and anchors, and is not warm started from this one.
uint64_t pair_key(int a, int b) {
  return (uint64_t(uint32_t(std::min(a, b))) << 33) | (uint64_t(uint32_t(std::max(a, b))) << 1) | uint64_t(a > b);
}

// A contact point's anchors, at the step's start.
ContactAnchors anchors_of(const Contact& contact, const std::vector<Body>& bodies) {
  ContactAnchors c;
  c.anchor_a = contact.point - bodies[contact.body_a].position;
  c.anchor_b = contact.point - bodies[contact.body_b].position;
  c.adjusted_separation = contact.separation - (c.anchor_a - c.anchor_b).dot(contact.normal);
  c.feature = contact.feature;
  return c;
}

}  // namespace

void ContactSolver::plan(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                        const std::vector<PairMaterial>& pair_materials, ThreadTeam& team, int threads) {
  team_ = &team;
  pair_materials_ = &pair_materials;
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
    // A manifold that can bounce is solved alone, in the contacts' order: a hit then passes along a
    // row of touching bodies within one sub-step (Newton's cradle), and pairs would reorder them.
    const bool can_bounce =
        contact_material(bodies[contact.body_a].material, bodies[contact.body_b].material, pair_materials).restitution > 0;
    items[k] = {moving(contact.body_a), moving(contact.body_b), bodies[contact.body_a].position, bodies[contact.body_b].position,
                can_bounce ? 0 : groups_[k].second - groups_[k].first};
  }
  schedule_.plan(items, int(bodies.size()), std::min(threads, team.size()));
}

void ContactSolver::prepare(const std::vector<Contact>& contacts, const std::vector<Body>& bodies, const SolverBodies& solver_bodies,
                            const ContactSolverSettings& settings, const Vec3& gravity, Real h) {
  settings_ = settings;
  gravity_ = gravity;
  impact_threshold_ = impact_threshold(settings.restitution_threshold, gravity);
  landing_speed_ = kLandingShare * impact_threshold_;
  const Real hertz = std::min(settings.contact_hertz, kMaxHertzPerSubstepRate / h);
  // One stiffness for every contact. Box2D makes contacts with static bodies twice as stiff; so
  // made, a 1 kg box between the ground and a 100 kg box rattles at 0.1-0.3 m/s for ever: its
  // contact with the ground, four times as stiff, and the one above it give it a mode at about
  // 2.2 times the contacts' frequency, beyond what a sub-step at 1/5 of its rate holds.
  softness_ = make_softness(hertz, settings.contact_damping_ratio, h);
  // The constraints are laid out in the sweeps' order: a thread's share is then one block of memory.
  const std::vector<int>& order = schedule_.order();
  // Last step's constraints, if it stored its impulses, are the warm start: found by pair, then
  // by feature. Each thread reads what it built last step.
  if (impulses_stored_) {
    std::swap(previous_pairs_, pairs_);
  } else {
    previous_pairs_.clear();
  }
  impulses_stored_ = false;
  // Impulses are per sub-step: when the sub-step changes length, so do they.
  const Real warm_scale = stored_h_ > 0 ? h / stored_h_ : 1;
  h_ = h;
  substeps_ = 0;
  resize_for_step(manifolds_, order.size());
  resize_for_step(constraints_, contacts.size());
  resize_for_step(constraint_of_contact_, contacts.size());
  resize_for_step(first_of_place_, order.size());
  resize_for_step(pairs_, order.size());
  for (size_t place = 0, next = 0; place < order.size(); ++place) {
    const auto [first, end] = groups_[order[place]];
    first_of_place_[place] = int(next);
    for (int i = first; i < end; ++i) constraint_of_contact_[i] = int(next++);
    pairs_[order[place]] = {pair_key(contacts[first].body_a, contacts[first].body_b), int(place)};
  }
  // Blocks of two manifolds side by side where the schedule paired them, else of one.
  world_slot_ = int(solver_bodies.states.size()) - 1;
  resize_for_step(lane_of_place_, order.size());
  int blocks = 0, points = 0;
  for (int place = 0; place < int(order.size()); ++blocks) {
    const int width = schedule_.paired(place) ? 2 : 1;
    for (int l = 0; l < width; ++l) lane_of_place_[place + l] = {blocks, l};
    place += width;
  }
  resize_for_step(lanes_, blocks);
  for (int place = 0, block = 0; place < int(order.size()); ++block) {
    lanes_[block].first_point = points;
    points += groups_[order[place]].second - groups_[order[place]].first;
    place += schedule_.paired(place) ? 2 : 1;
  }
  resize_for_step(lane_points_, points);
  resize_for_step(impact_shift_, contacts.size());  // written for the points that bounce (ManifoldConstraint::hit_points)
  find_previous_pairs();
  // Each thread builds the manifolds it sweeps, from the states and bodies it loaded.
  schedule_.run(*team_, [&](int thread) {
    schedule_.place_share(thread, [&](int place) { prepare_manifold(place, contacts, bodies, solver_bodies, warm_scale); });
  });
}

// The manifold at `place`: its points' constraints, warm started from last step's impulses of the
// same pair and feature, its shared rows, and its lane.
void ContactSolver::prepare_manifold(int place, const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                                     const SolverBodies& solver_bodies, Real warm_scale) {
  const std::vector<int>& slots = schedule_.slots();
  const int manifold = schedule_.order()[place];
  const auto [first, end] = groups_[manifold];
  ManifoldConstraint& m = manifolds_[place];
  m = ManifoldConstraint{};
  m.a = slots[contacts[first].body_a];
  m.b = slots[contacts[first].body_b];
  m.first = first_of_place_[place];
  m.count = end - first;
  // What the points share: the pair's normal (the contacts of a manifold have one), its tangents, the materials.
  const Body& body_a = bodies[contacts[first].body_a];
  const Body& body_b = bodies[contacts[first].body_b];
  m.normal = contacts[first].normal;
  tangent_basis(m.normal, m.tangent1, m.tangent2);
  const ContactMaterial material = contact_material(body_a.material, body_b.material, *pair_materials_);
  m.friction = settings_.friction ? material.friction : 0;
  m.restitution = material.restitution;
  const auto [same_pair, other_pair] = previous_range_[manifold];
  // The friction's warm start: last step's manifold of the pair that shares a point with this one
  // (a mesh's pair has one per triangle normal), else its last.
  int friction_from = other_pair - 1;
  ContactAnchors anchors[kMaxManifoldPoints];
  for (int i = 0; i < m.count; ++i) {
    anchors[i] = anchors_of(contacts[first + i], bodies);
    ContactConstraint& c = constraints_[m.first + i];
    c = ContactConstraint{};
    c.feature = anchors[i].feature;
    for (int previous = same_pair; previous != other_pair; ++previous) {
      const ManifoldWarm& pm = warm_manifolds_[previous_pairs_[previous].manifold];
      for (int j = 0; j < pm.count; ++j)
        if (warm_points_[pm.first + j].feature == c.feature) {
          c.normal_impulse = warm_scale * warm_points_[pm.first + j].normal_impulse;
          friction_from = previous;
        }
    }
  }
  ManifoldLanes& block = begin_lanes(place, m);
  prepare_shared_rows(m, anchors, block, lane_of_place_[place].lane, body_a, body_b, solver_bodies);
  if (same_pair != other_pair) {
    warm_start_friction(m, warm_manifolds_[previous_pairs_[friction_from].manifold]);
    m.tangent_impulse1 *= warm_scale;
    m.tangent_impulse2 *= warm_scale;
    m.twist_impulse *= warm_scale;
  }
  fill_lanes(place, m, anchors);
}

void set_rows(ManifoldLanes& block, PointLanes* points, int l, const RowGeometry& g, const Real* soft_share) {
  const Mat3& inv_ia = *g.inv_inertia_a;
  const Mat3& inv_ib = *g.inv_inertia_b;
  const Real linear = g.inv_mass_a + g.inv_mass_b;
  for (int i = 0; i < g.count; ++i) {
    const Vec3 ra_cross_n = g.ra[i].cross(g.normal), rb_cross_n = g.rb[i].cross(g.normal);
    const Vec3 angular_a = inv_ia * ra_cross_n, angular_b = inv_ib * rb_cross_n;
    PointLanes& p = points[i];
    set_lane(p.ra_cross_n, l, ra_cross_n);
    set_lane(p.rb_cross_n, l, rb_cross_n);
    set_lane(p.angular_a, l, angular_a);
    set_lane(p.angular_b, l, angular_b);
    p.normal_mass[l] = safe_inverse(inverse_effective_mass_of_rows(linear, ra_cross_n, angular_a, rb_cross_n, angular_b));
  }
  // How an impulse at point j changes the normal velocity at point i. Symmetric, and the points
  // share the normal.
  for (int i = 0; i < g.count; ++i)
    for (int j = i; j < g.count; ++j)
      block.coupling[i][j][l] = block.coupling[j][i][l] =
          inverse_effective_mass_of_rows(linear * g.normal.dot(g.normal), lane(points[i].ra_cross_n, l), lane(points[j].angular_a, l),
                                         lane(points[i].rb_cross_n, l), lane(points[j].angular_b, l));
  if (soft_share) factor_touching_points(block.factors[0], block.factors[1], block.coupling, g.count, l, *soft_share);
  else block.factors[0].pattern[l] = block.factors[1].pattern[l] = 0;
  set_friction_rows(block, l, g);
}

void set_friction_rows(ManifoldLanes& block, int l, const RowGeometry& g) {
  const Mat3& inv_ia = *g.inv_inertia_a;
  const Mat3& inv_ib = *g.inv_inertia_b;
  block.tangent_mass1[l] = safe_inverse(inverse_effective_mass(g.inv_mass_a, inv_ia, g.inv_mass_b, inv_ib, g.centre_a, g.centre_b, g.tangent1));
  block.tangent_mass2[l] = safe_inverse(inverse_effective_mass(g.inv_mass_a, inv_ia, g.inv_mass_b, inv_ib, g.centre_a, g.centre_b, g.tangent2));
  block.twist_mass[l] = safe_inverse(g.normal.dot((inv_ia + inv_ib) * g.normal));
  const Vec3 ra_cross_t1 = g.centre_a.cross(g.tangent1), ra_cross_t2 = g.centre_a.cross(g.tangent2);
  const Vec3 rb_cross_t1 = g.centre_b.cross(g.tangent1), rb_cross_t2 = g.centre_b.cross(g.tangent2);
  set_lane(block.ra_cross_t1, l, ra_cross_t1);
  set_lane(block.ra_cross_t2, l, ra_cross_t2);
  set_lane(block.rb_cross_t1, l, rb_cross_t1);
  set_lane(block.rb_cross_t2, l, rb_cross_t2);
  set_lane(block.turn_a1, l, inv_ia * ra_cross_t1);
  set_lane(block.turn_a2, l, inv_ia * ra_cross_t2);
  set_lane(block.turn_b1, l, inv_ib * rb_cross_t1);
  set_lane(block.turn_b2, l, inv_ib * rb_cross_t2);
  set_lane(block.twist_a, l, inv_ia * g.normal);
  set_lane(block.twist_b, l, inv_ib * g.normal);
}

// For each of this step's manifolds (in the contacts' order), the range of last step's with the
// same pair. Both lists come by pair, as the contacts do (ContactFinder): one merge, no search.
void ContactSolver::find_previous_pairs() {
  auto by_pair = [](const PairPlace& x, const PairPlace& y) { return x.key != y.key ? x.key < y.key : x.manifold < y.manifold; };
  if (!std::is_sorted(previous_pairs_.begin(), previous_pairs_.end(), by_pair)) std::sort(previous_pairs_.begin(), previous_pairs_.end(), by_pair);
  resize_for_step(previous_range_, pairs_.size());
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

// The shared parts of a manifold whose points are built, and the rows its lane `l` of `block` is
// solved with: each point's at its anchors, their coupling, friction at their centroid.
void ContactSolver::prepare_shared_rows(ManifoldConstraint& m, const ContactAnchors* points, ManifoldLanes& block, int l, const Body& body_a,
                                        const Body& body_b, const SolverBodies& solver_bodies) {
  const BodyState& sa = solver_bodies.states[m.a];
  const BodyState& sb = solver_bodies.states[m.b];
  const ContactAnchors& first = points[0];
  block.can_bounce = block.can_bounce || m.restitution > 0;
  Vec3 centre = Vec3::Zero(), ra[kMaxManifoldPoints], rb[kMaxManifoldPoints];
  for (int i = 0; i < m.count; ++i) {
    ra[i] = points[i].anchor_a;
    rb[i] = points[i].anchor_b;
    centre += points[i].anchor_a;
  }
  centre /= m.count;  // relative to A
  PointLanes* lanes = &lane_points_[block.first_point];
  const Real share = soft_share(softness_);
  set_rows(block, lanes, l,
           {m.normal, m.tangent1, m.tangent2, m.count, ra, rb, centre, centre + (first.anchor_b - first.anchor_a), sa.inv_mass, sb.inv_mass,
            &solver_bodies.inertia[m.a].inv_inertia, &solver_bodies.inertia[m.b].inv_inertia},
           &share);
  for (int i = 0; i < m.count; ++i) constraints_[m.first + i].normal_mass = lanes[i].normal_mass[l];
  Real twist_radius = 0;
  for (int i = 0; i < m.count; ++i) twist_radius += (points[i].anchor_a - centre).norm() / m.count;
  m.radius_a = body_a.shape.type == ShapeType::sphere ? body_a.shape.radius : 0;
  m.radius_b = body_b.shape.type == ShapeType::sphere ? body_b.shape.radius : 0;
  // One point of a sphere: the soft contact presses a disc of radius a = sqrt(2 R d) at depth d
  // (R = 1 / (1/R_a + 1/R_b), a flat face's 1/R being 0), over which friction resists a twist up
  // to 2/3 mu N a (uniform pressure). Without it a sphere spinning about the normal spins for ever.
  if (m.count == 1) {
    const Real k = (m.radius_a > 0 ? 1 / m.radius_a : 0) + (m.radius_b > 0 ? 1 / m.radius_b : 0);
    const Real depth = std::max(-(first.adjusted_separation + (first.anchor_a - first.anchor_b).dot(m.normal)), Real(0));
    if (k > 0) twist_radius = Real(2) / 3 * std::sqrt(2 * depth / k);
    if (k > 0) block.rolling_radius[l] = settings_.rolling_resistance / k;
  }
  block.twist_radius[l] = twist_radius;
  // A sphere's surface stays where it is as it turns, a round side nearly so (manifold.h), and a still body does not turn.
  m.turns_a = sa.inv_mass > 0 && m.radius_a == 0 && !feature::round_of(first.feature, 0);
  m.turns_b = sb.inv_mass > 0 && m.radius_b == 0 && !feature::round_of(first.feature, 1);
  block.turns_a[l] = m.turns_a;
  block.turns_b[l] = m.turns_b;
  // A face's normal turns with its box: an incident corner is measured from the face as it is now.
  const int reference = feature::face_of(first.feature);
  const bool turns = reference == 0 ? m.turns_a : reference == 1 ? m.turns_b : false;
  block.face_of[l] = turns ? reference + 1 : 0;
  set_lane(block.centres, l, first.anchor_a - first.anchor_b);
}

// The block of a place's manifold, its lane given the manifold's bodies (and emptied first, with
// its second lane left still, by the block's first manifold).
ManifoldLanes& ContactSolver::begin_lanes(int place, const ManifoldConstraint& m) {
  const auto [index, l] = lane_of_place_[place];
  ManifoldLanes& block = lanes_[index];
  if (l == 0) {
    const int first_point = block.first_point;
    block = ManifoldLanes{};
    block.points = m.count;
    block.first_point = first_point;
    block.a[1] = block.b[1] = world_slot_;
    for (int i = 0; i < m.count; ++i) lane_points_[first_point + i] = PointLanes{};
  }
  block.a[l] = m.a;
  block.b[l] = m.b;
  return block;
}

// The rest of a prepared manifold's lane (prepare_shared_rows() wrote its rows): the shared normal
// and tangents, the warm start, and the points' anchors and impulses.
void ContactSolver::fill_lanes(int place, const ManifoldConstraint& m, const ContactAnchors* anchors) {
  const auto [index, l] = lane_of_place_[place];
  ManifoldLanes& block = lanes_[index];
  set_lane(block.normal, l, m.normal);
  set_lane(block.tangent1, l, m.tangent1);
  set_lane(block.tangent2, l, m.tangent2);
  block.friction[l] = m.friction;
  block.tangent_impulse1[l] = m.tangent_impulse1;
  block.tangent_impulse2[l] = m.tangent_impulse2;
  block.twist_impulse[l] = m.twist_impulse;
  for (int i = 0; i < m.count; ++i) {
    PointLanes& p = lane_points_[block.first_point + i];
    set_lane(p.anchor_a, l, anchors[i].anchor_a);
    set_lane(p.anchor_b, l, anchors[i].anchor_b);
    p.adjusted_separation[l] = anchors[i].adjusted_separation;
    p.normal_impulse[l] = constraints_[m.first + i].normal_impulse;
  }
}

// Last step's friction impulses, on this step's tangents.
void ContactSolver::warm_start_friction(ManifoldConstraint& m, const ManifoldWarm& previous) {
  m.tangent_impulse1 = previous.friction_impulse.dot(m.tangent1);
  m.tangent_impulse2 = previous.friction_impulse.dot(m.tangent2);
  m.twist_impulse = previous.twist_impulse;
}

}  // namespace impulse::physics
