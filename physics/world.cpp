#include "physics/world.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impulse::physics {

World::World(WorldSettings settings) : settings_(settings) {
  if (!(settings_.time_step > 0)) throw std::invalid_argument("time_step must be > 0");
  if (settings_.substeps < 1) throw std::invalid_argument("substeps must be >= 1");
  if (settings_.min_substeps < 1) throw std::invalid_argument("min_substeps must be >= 1");
  if (!(settings_.moving_overlap >= 0)) throw std::invalid_argument("moving_overlap must be >= 0 (0: off)");
  if (!(settings_.stack_sink >= 0)) throw std::invalid_argument("stack_sink must be >= 0 (0: always `substeps` sub-steps)");
  if (settings_.threads < 0) throw std::invalid_argument("threads must be >= 0 (0: one per core)");
  if (settings_.response && settings_.method != ResponseMethod::workshop)
    throw std::invalid_argument("an outside response takes the place of listing 1's page: it needs the workshop method");
  if (settings_.reference_listing && (settings_.method != ResponseMethod::workshop || settings_.response || settings_.printed_eq8_sign))
    throw std::invalid_argument("the reference listing is the workshop method's page, alone: no response, no printed eq. 8");
  if (settings_.response) response_ = settings_.response();
  substeps_ = settings_.substeps;
  team_ = std::make_unique<ThreadTeam>(settings_.threads > 0 ? settings_.threads : ThreadTeam::default_size());
  share_chooser_ = ShareChooser(settings_.threads == 0 && team_->size() > 1);
}

int World::add_body(const BodyDef& def) {
  bodies_.push_back(make_body(def));
  return int(bodies_.size()) - 1;
}

int World::add_joint(const JointDef& def) {
  joints_.push_back(make_joint(def, bodies_));
  if (def.body_a != kWorld && def.body_b != kWorld) links_.emplace_back(def.body_a, def.body_b);
  else if (def.body_a != kWorld || def.body_b != kWorld) anchored_.push_back(def.body_a != kWorld ? def.body_a : def.body_b);
  return int(joints_.size()) - 1;
}

void World::step() {
  const Real dt = settings_.time_step;
  const auto started = std::chrono::steady_clock::now();
  const int threads = share_chooser_.next_step_shares() ? team_->size() : 1;

  find_contacts(threads);
  substeps_ = choose_substeps();
  const Real h = dt / substeps_;
  // A bounce holds the joints of its bodies (contact_bounce.cpp), which reach beyond its two
  // bodies: with joints, one thread sweeps the contacts (the bits are the same for any count).
  contact_solver_.plan(contacts_, bodies_, settings_.pair_materials, *team_, joints_.empty() ? threads : 1);
  load_states();
  if (settings_.method == ResponseMethod::impulse)
    contact_solver_.prepare(contacts_, bodies_, solver_bodies_, settings_.contact, settings_.gravity, h);
  else
    teaching_impulses_.assign(contacts_.size(), TeachingImpulse{});
  const Real joint_step = settings_.method == ResponseMethod::workshop || settings_.method == ResponseMethod::projection ? dt : h;
  joint_solver_.prepare(joints_, bodies_, contact_solver_.slots(), settings_.joint_hertz, settings_.joint_damping_ratio, joint_step);
  respond(dt, h);

  store_states();
  islands_.update(bodies_, contacts_, links_, anchored_, settings_.contact.friction, settings_.linear_slop, dt,
                  settings_.sleep);
  time_ += dt;
  ++step_count_;
  share_chooser_.step_took(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
                           double(contacts_.size()) * substeps_ + double(bodies_.size()));
  check_finite();
}

ContactMaterial World::contact_material(int body_a, int body_b) const {
  ContactMaterial material = physics::contact_material(bodies_.at(body_a).material, bodies_.at(body_b).material, settings_.pair_materials);
  if (!settings_.contact.friction) material.friction = 0;
  return material;
}

const StepRecord& World::record() const {
  if (recorded_step_ != step_count_) fill_record();
  recorded_step_ = step_count_;
  return record_;
}

namespace {

constexpr Real kSecondsBeforeFewer = 1;

}  // namespace

// Fewer sub-steps while every stack would sink less than settings_.stack_sink into its soft
// contacts at the stiffness they allow (stack_sink.h) and no moving body overlaps another more
// than settings_.moving_overlap (else the most); more at once when a load comes.
int World::choose_substeps() {
  const bool adapts = settings_.method == ResponseMethod::impulse && settings_.stack_sink > 0 &&
                      settings_.min_substeps < settings_.substeps && settings_.gravity.squaredNorm() > 0;
  if (!adapts) return settings_.substeps;
  const Real give = stack_sink_.deepest_give(contact_solver_, bodies_, -settings_.gravity.normalized(), settings_.time_step / substeps_);
  const Real hertz = std::min(std::sqrt(give / settings_.stack_sink) / (2 * kPi), settings_.contact.contact_hertz);
  int needed = std::clamp(int(std::ceil(hertz * settings_.time_step / kMaxHertzPerSubstepRate)), settings_.min_substeps, settings_.substeps);
  if (settings_.moving_overlap > 0 && moving_overlap_too_deep(contacts_, bodies_, settings_.moving_overlap, settings_.sleep.velocity_tolerance))
    needed = settings_.substeps;
  // Each change of stiffness moves every resting body a little (its contacts settle anew): fewer
  // only after a second of needing fewer, and then at once to the most that second needed, so that
  // a settling pile changes once rather than at every step.
  if (needed >= substeps_) {
    fewer_since_ = 0;
    most_needed_lately_ = 0;
    return needed;
  }
  most_needed_lately_ = std::max(most_needed_lately_, needed);
  if (++fewer_since_ * settings_.time_step < kSecondsBeforeFewer) return substeps_;
  const int fewer = most_needed_lately_;
  fewer_since_ = 0;
  most_needed_lately_ = 0;
  return fewer;
}

void World::find_contacts(int threads) {
  // Contacts of awake bodies; a sleeping island they reach wakes, and then its own contacts count.
  do {
    awake_.resize(bodies_.size());
    for (size_t i = 0; i < bodies_.size(); ++i) awake_[i] = !bodies_[i].is_static() && bodies_[i].awake;
    contact_finder_.find(bodies_, awake_, settings_.time_step, 4 * settings_.linear_slop, *team_, threads, contacts_);
  } while (islands_.wake_touched(bodies_, contacts_, links_, settings_.linear_slop, settings_.sleep));
}

// Each thread loads (and later stores) the bodies whose sweeps it solves: their data then stays in
// its core's cache.
void World::load_states() {
  solver_bodies_.states.resize(bodies_.size() + 1);
  solver_bodies_.inertia.resize(bodies_.size() + 1);
  solver_bodies_.warm.resize(bodies_.size() + 1);
  solver_bodies_.states.back() = BodyState{};  // the world, for joints fixed in it: static
  solver_bodies_.inertia.back() = BodyInertia{};
  solver_bodies_.warm.back() = WarmStartChange{};
  contact_solver_.for_each_slot([&](int slot) {
    Body& body = bodies_[contact_solver_.body_of_slot()[slot]];
    body.refresh_world_inertia();
    BodyState& s = solver_bodies_.states[slot];
    s.v = body.velocity;
    s.w = body.angular_velocity;
    hold_in_plane(s.v, s.w, body.planar_axis);  // a caller may have set the body's velocities
    s.dp.setZero();
    s.dq = Quat::Identity();
    // A sleeping body is not simulated: to the solver it is as good as static.
    s.inv_mass = body.awake ? body.inv_mass : 0;
    BodyInertia& inertia = solver_bodies_.inertia[slot];
    inertia.inv_inertia = body.awake ? body.inv_inertia_world : Mat3::Zero();
    inertia.inertia_local = body.inertia_local.diagonal();
    inertia.orientation0 = body.orientation;
    // A planar body turns about its axis only, and the lock takes the whole gyroscopic torque (planar.h).
    inertia.planar_axis = body.planar_axis;
    inertia.gyroscopic = s.inv_mass > 0 && body.planar_axis == kNotPlanar &&
                         inertia.inertia_local.maxCoeff() - inertia.inertia_local.minCoeff() > 1e-9 * inertia.inertia_local.maxCoeff();
  });
}

void World::integrate_velocities(Real h) {
  contact_solver_.for_each_slot([&](int slot) { integrate_velocity(solver_bodies_.states[slot], solver_bodies_.inertia[slot], h); });
}

// Gravity; a planar body's lock takes its part along the axis before any contact sees it.
void World::integrate_velocity(BodyState& s, const BodyInertia& inertia, Real h) const {
  if (s.inv_mass == 0) return;
  s.v += settings_.gravity * h;
  hold_in_plane(s.v, s.w, inertia.planar_axis);
}

void World::integrate_positions(Real h) {
  contact_solver_.for_each_slot([&](int slot) { integrate_position(solver_bodies_.states[slot], solver_bodies_.inertia[slot], h); });
}

namespace {

constexpr int kNewtonIterations = 12;  // per solve; from the start velocity it converges in 3 to 5
constexpr int kMostHalvings = 8;       // a step is split at most 2^8 ways when Newton does not converge
constexpr Real kResidual = 1e-13;      // relative to |I w|: far below what would show in E or L in a minute

// The implicit midpoint rule for Euler's equations I dw/dt = -w x I w in the body frame (I
// diagonal): I (w1 - w0) = -h wm x I wm with wm = (w0 + w1) / 2. It keeps both quadratic
// invariants exactly, whatever h: dotting with wm gives E1 - E0 = wm . I (w1 - w0) = 0, and with
// I wm gives (|I w1|^2 - |I w0|^2) / 2 = 0. Solved as I wm + h/2 wm x I wm = I w0 (an implicit
// Euler half step) by Newton's method to a residual at rounding level; then w1 = 2 wm - w0.
// Returns false when Newton does not get there.
bool midpoint_rotation(const Vec3& inertia, const Vec3& w0, Real h, Vec3& wm, Vec3& w1) {
  const Vec3 l0 = inertia.cwiseProduct(w0);
  const Real half = h / 2;
  const Mat3 inertia_matrix = inertia.asDiagonal();
  wm = w0;
  for (int i = 0; i < kNewtonIterations; ++i) {
    const Vec3 iw = inertia.cwiseProduct(wm);
    const Vec3 residual = iw + half * wm.cross(iw) - l0;
    if (residual.norm() <= kResidual * (l0.norm() + half * wm.norm() * iw.norm())) {
      w1 = 2 * wm - w0;
      return true;
    }
    const Mat3 jacobian = inertia_matrix + half * (skew(wm) * inertia_matrix - skew(iw));
    wm -= jacobian.partialPivLu().solve(residual);
  }
  return false;
}

// Torque-free rotation over h: the body turns by cay(h wm) (world frame) while its body-frame
// angular momentum goes from I w0 to I w1 = cay(-h wm) I w0, the same rule read as a rotation
// ((1 + h/2 [wm]x) I w1 = (1 - h/2 [wm]x) I w0). So the world-frame momentum R I w is kept
// exactly, and with it |L|, and the energy by the midpoint rule. When Newton fails (a very fast
// spin), the step is split in halves, each such a step.
void turn_free(const Vec3& inertia, const Quat& orientation0, Quat& dq, Vec3& w, Real h, int halvings) {
  const Quat orientation = dq * orientation0;
  Vec3 wm, w1;
  if (midpoint_rotation(inertia, orientation.conjugate() * w, h, wm, w1)) {
    turn(dq, orientation * wm, h);
    w = (dq * orientation0) * w1;
    return;
  }
  if (halvings == kMostHalvings || !is_finite(w)) {  // turning about w keeps w in the body frame,
    turn(dq, w, h);                                  // and so E and |L|
    return;
  }
  turn_free(inertia, orientation0, dq, w, h / 2, halvings + 1);
  turn_free(inertia, orientation0, dq, w, h / 2, halvings + 1);
}

}  // namespace

// A body whose inertia is not the same about every axis carries the gyroscopic term here, where
// it turns (turn_free): a tumbling plank keeps its angular momentum and energy, a box spun about
// its middle axis flips for ever, and a fast thin one cannot gain energy.
void World::integrate_position(BodyState& s, const BodyInertia& inertia, Real h) {
  if (s.inv_mass == 0) return;
  hold_in_plane(s.v, s.w, inertia.planar_axis);  // what the contacts and joints left, in the plane
  s.dp += s.v * h;
  if (inertia.gyroscopic)
    turn_free(inertia.inertia_local, inertia.orientation0, s.dq, s.w, h, 0);
  else
    turn(s.dq, s.w, h);
}

// Each thread stores, and checks, the bodies it solved: their lines stay in its core's cache.
void World::store_states() {
  non_finite_body_->store(int(bodies_.size()), std::memory_order_relaxed);
  contact_solver_.for_each_slot([&](int slot) {
    const int index = contact_solver_.body_of_slot()[slot];
    Body& body = bodies_[index];
    if (!body.is_static() && body.awake) {
      const BodyState& s = solver_bodies_.states[slot];
      body.velocity = s.v;
      body.angular_velocity = s.w;
      Vec3 dp = s.dp;
      if (body.planar_axis != kNotPlanar) {
        // The relax pass's velocities, and a bounce's or a teaching page's shift, held in the plane.
        hold_in_plane(body.velocity, body.angular_velocity, body.planar_axis);
        dp[body.planar_axis] = 0;
      }
      body.position += dp;
      body.orientation = (s.dq * body.orientation).normalized();
    }
    // Every body, still ones too: a caller may have set a sleeping body's state between steps.
    if (is_finite(body.position) && is_finite(body.orientation) && is_finite(body.velocity) && is_finite(body.angular_velocity)) return;
    int lowest = non_finite_body_->load(std::memory_order_relaxed);  // the same body named, however many threads
    while (index < lowest && !non_finite_body_->compare_exchange_weak(lowest, index, std::memory_order_relaxed)) {
    }
  });
}

void World::check_finite() const {
  const int index = non_finite_body_->load(std::memory_order_relaxed);
  if (index >= int(bodies_.size())) return;
  throw std::runtime_error("body '" + bodies_[index].name + "' (index " + std::to_string(index) + ") has a non-finite state after step " +
                           std::to_string(step_count_) + " (t = " + std::to_string(time_) + " s)");
}

void World::fill_record() const {
  record_.step = step_count_;
  record_.time = time_;
  record_.contacts.clear();
  const bool teaching = settings_.method != ResponseMethod::impulse;
  for (size_t i = 0; i < contacts_.size(); ++i) {
    const Contact& contact = contacts_[i];
    Real normal_impulse;
    Vec3 friction_impulse, point = contact.point, normal = contact.normal;
    if (teaching) {
      const TeachingImpulse& t = teaching_impulses_[i];
      Vec3 t1, t2;
      tangent_basis(contact.normal, t1, t2);
      normal_impulse = t.normal;
      friction_impulse = t.tangent1 * t1 + t.tangent2 * t2;
    } else {
      // A point that bounced: where the surfaces met, and the normal then (contact_bounce.cpp).
      const ContactConstraint& c = contact_solver_.constraint_of(int(i));
      const ManifoldConstraint& m = contact_solver_.manifold_of(int(i));
      normal_impulse = c.total_normal_impulse;
      friction_impulse = c.total_tangent_impulse1 * m.tangent1 + c.total_tangent_impulse2 * m.tangent2;
      point += contact_solver_.impact_shift(int(i));
      normal = m.normal;
    }
    if (contact.separation > settings_.linear_slop && normal_impulse == 0) continue;
    record_.contacts.push_back({contact.body_a, contact.body_b, point, normal, contact.penetration(), normal_impulse, friction_impulse});
  }
  record_.joints.clear();
  for (const Joint& j : joints_) {
    auto world_point = [&](int body, const Vec3& local) {
      return body == kWorld ? local : Vec3(bodies_[body].position + bodies_[body].orientation * local);
    };
    record_.joints.push_back({j.type, j.body_a, j.body_b, world_point(j.body_a, j.local_anchor_a), world_point(j.body_b, j.local_anchor_b)});
  }
  record_.kinetic_energy = 0;
  record_.potential_energy = 0;
  record_.linear_momentum.setZero();
  record_.angular_momentum.setZero();
  for (const Body& b : bodies_) {
    if (b.is_static()) continue;
    const Mat3 inertia = b.inertia_world();
    record_.kinetic_energy += b.mass * b.velocity.squaredNorm() / 2 + b.angular_velocity.dot(inertia * b.angular_velocity) / 2;
    record_.potential_energy -= b.mass * settings_.gravity.dot(b.position);
    record_.linear_momentum += b.mass * b.velocity;
    record_.angular_momentum += b.position.cross(b.mass * b.velocity) + inertia * b.angular_velocity;
  }
}

}  // namespace impulse::physics
