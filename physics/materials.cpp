#include "physics/materials.h"

#include <algorithm>
#include <cmath>

namespace impulse::physics {

Real mix_restitution(Real a, Real b) { return std::max(a, b); }
Real mix_friction(Real a, Real b) { return std::sqrt(a * b); }

ContactMaterial contact_material(const Material& a, const Material& b, const std::vector<PairMaterial>& pairs) {
  ContactMaterial mixed{mix_friction(a.friction, b.friction), mix_restitution(a.restitution, b.restitution)};
  if (a.kind < 0 || b.kind < 0) return mixed;
  for (auto pair = pairs.rbegin(); pair != pairs.rend(); ++pair) {
    if (!((pair->kind_a == a.kind && pair->kind_b == b.kind) || (pair->kind_a == b.kind && pair->kind_b == a.kind))) continue;
    if (pair->friction) mixed.friction = *pair->friction;
    if (pair->restitution) mixed.restitution = *pair->restitution;
    break;
  }
  return mixed;
}

}  // namespace impulse::physics
