// Contacts of a step: sweep-and-prune pairs, then the narrow phase on each.
#include "physics/contact_finder.h"

#include "physics/collide.h"

namespace impulse::physics {

Real motion_bound(const Body& body, Real dt) {
  return (body.velocity.norm() + body.angular_velocity.norm() * bounding_radius(body.shape)) * dt;
}

void ContactFinder::find(const std::vector<Body>& bodies, const std::vector<uint8_t>& awake, Real dt,
                         Real base_margin, std::vector<Contact>& out) {
  out.clear();
  // Each box grows by its body's share of a pair's margin, so that two boxes overlap whenever
  // their shapes are within base_margin + motion_bound(a) + motion_bound(b).
  const size_t n = bodies.size();
  boxes_.resize(n);
  motion_bounds_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    motion_bounds_[i] = motion_bound(bodies[i], dt);
    boxes_[i] = body_aabb(bodies[i], base_margin / 2 + motion_bounds_[i]);
  }
  broad_phase_.find_pairs(boxes_, awake, pairs_);
  for (const BodyPair& pair : pairs_) {
    const Real margin = base_margin + motion_bounds_[pair.a] + motion_bounds_[pair.b];
    collide(bodies[pair.a], pair.a, bodies[pair.b], pair.b, margin, out);
  }
}

}  // namespace impulse::physics
