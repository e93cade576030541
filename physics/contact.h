// The workshop's contact data: contact point, normal and penetration, for one pair of bodies.
#pragma once
#include "physics/math.h"

#include <cstdint>

namespace impulse::physics {

// Convention (the workshop's, section 3): `normal` is the unit direction in which body A must
// move to leave body B. `separation` is the gap between the surfaces along the normal: negative
// when they overlap (penetration = -separation), positive for a speculative contact that is not
// touching yet. `point` lies midway between the two surfaces.
struct Contact {
  int body_a = -1;
  int body_b = -1;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitY();
  Real separation = 0;
  uint32_t feature = 0;  // identifies the point within its pair across steps (warm starting)

  Real penetration() const { return -separation; }
};

}  // namespace impulse::physics
