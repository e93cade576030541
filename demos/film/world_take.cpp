#include "demos/film/world_take.h"

#include "demos/film/impulse_label.h"
#include "demos/scene/scene_world.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace impulse::demos {
namespace {

// Slow motion, automatic arrow scales, plots and the impulse label (which skips impulses
// negligible beside the largest) read the summary; without them it stays empty.
bool needs_summary(const Scene& scene) {
  const DrawOptions& draw = scene.draw;
  const bool auto_impulse = (draw.impulses || draw.friction) && draw.impulse_scale <= 0;
  const bool auto_velocity = draw.velocities && draw.velocity_scale <= 0;
  return scene.playback.slow_motion_impulse > 0 || auto_impulse || auto_velocity || !scene.overlay.plots.empty() ||
         scene.overlay.label == "impulse";
}

}  // namespace

WorldTake::WorldTake(const Scene& scene)
    : scene_(scene),
      world_(build_world(scene)),
      bodies_(world_.bodies()),
      contacts_drawn_(scene.draw.contact_points || scene.draw.contact_normals || scene.draw.impulses ||
                      scene.draw.friction),
      checks_(scene.checks),
      plots_(scene.overlay.plots, plotted_bodies(bodies_, scene.overlay.plot_bodies), scene.overlay.plot_from),
      hold_(scene.draw.contact_hold),
      before_(poses_of(bodies_)),
      after_(before_) {
  for (const physics::Body& body : bodies_) {
    velocities_.push_back(body.velocity);
    angular_velocities_.push_back(body.angular_velocity);
    awake_.push_back(body.awake);
    if (!body.is_static()) weight_impulse_ += body.mass * scene.world.gravity.norm() * scene.world.time_step;
  }
  checks_.start(world_);
}

bool WorldTake::finished() const { return !(world_.time() < scene_.duration + 0.5 * scene_.world.time_step); }

void WorldTake::step() {
  std::vector<Motion> before;
  if (shows_impact_numbers(scene_))
    for (const physics::Body& body : world_.bodies())
      before.push_back({body.position, body.velocity, body.angular_velocity, body.inv_inertia_world});
  world_.step();
  if (!before.empty()) note_impact(before);
  checks_.step(world_);
  const physics::StepRecord& record = world_.record();
  const auto& bodies = world_.bodies();
  if (needs_summary(scene_)) {
    const double threshold = scene_.playback.slow_motion_impulse;
    bool impact = false;
    double step_largest = 0;
    for (const physics::ContactRecord& contact : record.contacts) {
      const bool moving = (contact.body_a >= 0 && !bodies[contact.body_a].is_static()) ||
                          (contact.body_b >= 0 && !bodies[contact.body_b].is_static());
      if (!moving) continue;
      step_largest = std::max({step_largest, double(contact.normal_impulse), double(contact.tangent_impulse.norm())});
      if (threshold > 0 && contact.normal_impulse >= threshold) impact = true;
    }
    summary_.largest_impulse = std::max(summary_.largest_impulse, step_largest);
    if (step_largest > 0) impulse_peaks_.push_back({record.time, step_largest, step_largest > kLoadShare * weight_impulse_});
    if (finished()) summary_.impulse_to_fit = impulse_to_fit(impulse_peaks_);
    if (impact) summary_.impact_times.push_back(record.time);
    for (const physics::Body& body : bodies)
      if (!body.is_static()) {
        summary_.largest_speed = std::max(summary_.largest_speed, double(body.velocity.norm()));
        const double reach = bounding_radius(body.shape);
        summary_.moving_extent.extend(Eigen::Vector3d(body.position.array() - reach));
        summary_.moving_extent.extend(Eigen::Vector3d(body.position.array() + reach));
      }
  }
  for (const physics::Body& body : bodies)
    for (const physics::Real x : {body.position.x(), body.position.y(), body.position.z(), body.orientation.w(),
                                  body.orientation.x(), body.orientation.y(), body.orientation.z(), body.velocity.x(),
                                  body.velocity.y(), body.velocity.z(), body.angular_velocity.x(), body.angular_velocity.y(),
                                  body.angular_velocity.z()}) {
      uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      motion_hash_ = (motion_hash_ ^ bits) * 0x100000001b3ull;
    }
  for (const physics::Body& body : bodies) summary_.someone_sleeps = summary_.someone_sleeps || (!body.is_static() && !body.awake);
  plots_.add_step(record, bodies);
  if (needs_summary(scene_)) summary_.plot_maxima = plots_.maxima();

  Step& kept = pending_.emplace_back();
  kept.time = record.time;
  kept.poses = poses_of(bodies);
  for (const physics::Body& body : bodies) {
    kept.velocities.push_back(body.velocity);
    kept.angular_velocities.push_back(body.angular_velocity);
    kept.awake.push_back(body.awake);
  }
  kept.contacts = record.contacts;
}

// The strongest contact of an impact step (one that slows the video), with the relative normal
// velocity its bodies had before the step: eq. 8's numbers, next to what the solver gave.
void WorldTake::note_impact(const std::vector<Motion>& before) {
  const double threshold = scene_.playback.slow_motion_impulse;
  if (!(threshold > 0)) return;  // no impacts without a threshold: resting contacts are none
  const physics::StepRecord& record = world_.record();
  const auto& bodies = world_.bodies();
  const physics::ContactRecord* strongest = nullptr;
  for (const physics::ContactRecord& contact : record.contacts)
    if (contact.normal_impulse >= threshold &&
        (strongest == nullptr || contact.normal_impulse > strongest->normal_impulse))
      strongest = &contact;
  if (strongest == nullptr) return;
  ImpactNumbers impact;
  impact.time = record.time;
  impact.body_a = strongest->body_a;
  impact.body_b = strongest->body_b;
  const physics::Vec3& n = strongest->normal;
  const Motion still{physics::Vec3::Zero(), physics::Vec3::Zero(), physics::Vec3::Zero(), physics::Mat3::Zero()};
  const Motion& a = impact.body_a >= 0 ? before[impact.body_a] : still;
  const Motion& b = impact.body_b >= 0 ? before[impact.body_b] : still;
  impact.approach = (a.velocity - b.velocity).dot(n);
  // Static bodies (and the world) neither move nor turn: their offset counts for nothing.
  auto moves = [&](int body) { return body >= 0 && !bodies[body].is_static(); };
  impact.offset_a = moves(impact.body_a) ? physics::Vec3(strongest->point - a.position) : physics::Vec3::Zero();
  impact.offset_b = moves(impact.body_b) ? physics::Vec3(strongest->point - b.position) : physics::Vec3::Zero();
  const physics::Vec3 point_a = a.velocity + a.angular_velocity.cross(impact.offset_a);
  const physics::Vec3 point_b = b.velocity + b.angular_velocity.cross(impact.offset_b);
  impact.point_approach = (point_a - point_b).dot(n);
  impact.angular = ((a.inverse_inertia * impact.offset_a.cross(n)).cross(impact.offset_a) +
                    (b.inverse_inertia * impact.offset_b.cross(n)).cross(impact.offset_b))
                       .dot(n);
  // The pair's e, as the solver takes it (its own, or the two bodies' mixed: physics/materials.h).
  impact.restitution = world_.contact_material(impact.body_a, impact.body_b).restitution;
  impact.inverse_mass_a = impact.body_a >= 0 ? bodies[impact.body_a].inv_mass : 0;
  impact.inverse_mass_b = impact.body_b >= 0 ? bodies[impact.body_b].inv_mass : 0;
  impact.impulse = strongest->normal_impulse;
  impacts_.push_back(impact);
}

void WorldTake::sample(double time, double video_time, FrameSample& sample) {
  // The steps until the world is at or past this frame's moment; the bodies are drawn in between.
  while (taken_time_ < time - 1e-9) {
    if (pending_.empty()) throw std::logic_error("WorldTake::sample: the frame is past the world's last step");
    Step& step = pending_.front();
    before_.swap(after_);
    after_ = std::move(step.poses);
    velocities_ = std::move(step.velocities);
    angular_velocities_ = std::move(step.angular_velocities);
    awake_ = std::move(step.awake);
    hold_.add_step(step.contacts, video_time);
    taken_time_ = step.time;
    ++steps_taken_;
    pending_.pop_front();
  }
  const double weight =
      steps_taken_ == 0 ? 1.0 : std::clamp(1.0 - (taken_time_ - time) / scene_.world.time_step, 0.0, 1.0);
  interpolate(before_, after_, weight, sample.poses);
  sample.velocities = velocities_;
  sample.angular_velocities = angular_velocities_;
  sample.awake = awake_;
  sample.contacts = hold_.shown(video_time);
  if (!contacts_drawn_) keep_label_candidate(sample.contacts);
  sample.plotted_steps = steps_taken_;
  while (impacts_shown_ < impacts_.size() && impacts_[impacts_shown_].time <= taken_time_ + 1e-9) ++impacts_shown_;
  if (impacts_shown_ > 0) sample.impact = impacts_[impacts_shown_ - 1];
}

// Without marks, a frame's contacts matter only to the impulse label: keep the one it would write.
void WorldTake::keep_label_candidate(std::vector<physics::ContactRecord>& contacts) const {
  const LabelledImpulse labelled =
      scene_.overlay.label == "impulse" ? labelled_impulse(contacts, bodies_, label_body(scene_)) : LabelledImpulse{};
  // A new vector, not the held contacts' capacity: frames are kept until the run ends.
  std::vector<physics::ContactRecord> kept;
  if (labelled.contact != nullptr) kept.push_back(*labelled.contact);
  contacts.swap(kept);
}

}  // namespace impulse::demos
