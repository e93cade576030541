#include "physics/contact_finder.h"

#include "physics/collide.h"

namespace impulse::physics {

Real motion_bound(const Body& body, Real dt) {
  const Real reach = body.shape.type == ShapeType::box ? body.shape.half_extents.norm() : body.shape.radius;
  return (body.velocity.norm() + body.angular_velocity.norm() * reach) * dt;
}

void ContactFinder::find(const std::vector<Body>& bodies, const std::vector<uint8_t>& awake, Real dt,
                         Real base_margin, std::vector<Contact>& out) {
  out.clear();
  // All pairs for now: O(n^2).
  for (int i = 0; i < int(bodies.size()); ++i) {
    for (int j = i + 1; j < int(bodies.size()); ++j) {
      if (!awake[i] && !awake[j]) continue;
      const Body& a = bodies[i];
      const Body& b = bodies[j];
      collide(a, i, b, j, base_margin + motion_bound(a, dt) + motion_bound(b, dt), out);
    }
  }
}

}  // namespace impulse::physics
