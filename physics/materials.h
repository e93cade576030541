// The material of a pair in contact: eq. 5's restitution e and Coulomb's friction mu. A scene may
// give a pair of materials its own (billiard balls on each other mu 0.05, on the cloth 0.2);
// otherwise the two bodies' are mixed (Box2D's rules): the larger restitution, and the geometric
// mean of the friction coefficients. Worked example: a ball of mu 0.05 on cloth of mu 0.2 slides
// with sqrt(0.05 * 0.2) = 0.1, and two balls on each other with 0.05.
#pragma once
#include "physics/body.h"

#include <optional>
#include <vector>

namespace impulse::physics {

// A scene's own values for contacts between bodies of two kinds (Material::kind, either order);
// a value left empty is mixed as usual.
struct PairMaterial {
  int kind_a = -1, kind_b = -1;
  std::optional<Real> friction, restitution;
};

struct ContactMaterial {
  Real friction = 0, restitution = 0;
};

Real mix_restitution(Real a, Real b);
Real mix_friction(Real a, Real b);

// The pair's: the last entry of `pairs` naming both kinds, else the mix.
ContactMaterial contact_material(const Material& a, const Material& b, const std::vector<PairMaterial>& pairs);

}  // namespace impulse::physics
