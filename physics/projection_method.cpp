#include "physics/projection_method.h"

namespace impulse::physics {

void project_apart(RigidBody& a, RigidBody& b, const Vec3& normal, Real penetration) {
  const Real total = a.inv_mass + b.inv_mass;
  if (penetration <= 0 || total == 0) return;
  a.displacement += normal * (penetration * a.inv_mass / total);
  b.displacement -= normal * (penetration * b.inv_mass / total);
}

}  // namespace impulse::physics
