#include "demos/scene/rotation_degrees.h"

#include <cmath>
#include <numbers>

namespace impulse::demos {

using physics::Quat;
using physics::Real;
using physics::Vec3;

std::pair<Real, Real> sin_cos_degrees(Real degrees) {
  // To r in [-45, 45] degrees from the nearest multiple of 90 (quadrant q): fmod and the
  // subtraction are exact.
  Real d = std::fmod(degrees, Real(360));
  if (d < 0) d += 360;
  int quadrant = 0;
  while (d - 90 * quadrant > 45) ++quadrant;
  const Real x = (d - 90 * quadrant) * (std::numbers::pi / 180);  // |x| <= pi/4
  // Taylor series to x^17 and x^18: the next terms are below 1e-19 for |x| <= pi/4.
  const Real x2 = x * x;
  Real s = 0, c = 0;
  for (int n = 17; n >= 3; n -= 2) s = (s + 1) * (-x2 / (Real(n) * Real(n - 1)));
  for (int n = 18; n >= 2; n -= 2) c = (c + 1) * (-x2 / (Real(n) * Real(n - 1)));
  s = x + x * s;
  c = 1 + c;
  switch (quadrant % 4) {
    case 1: return {c, -s};
    case 2: return {-s, -c};
    case 3: return {-c, s};
    default: return {s, c};
  }
}

Quat rotation_from_degrees(const Vec3& degrees) {
  auto turn = [](Real angle, const Vec3& axis) {
    const auto [sin_half, cos_half] = sin_cos_degrees(angle / 2);
    return Quat(cos_half, sin_half * axis.x(), sin_half * axis.y(), sin_half * axis.z());
  };
  return turn(degrees.z(), Vec3::UnitZ()) * turn(degrees.y(), Vec3::UnitY()) * turn(degrees.x(), Vec3::UnitX());
}

}  // namespace impulse::demos
