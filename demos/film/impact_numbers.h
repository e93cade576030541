// What the equations on screen are filled in with (live_equations.h): an impact's numbers, as the
// film's take notes them (world_take.h).
#pragma once
#include "demos/scene/scene.h"
#include "physics/math.h"

namespace impulse::demos {

// An impact's numbers, for eq. 8 and 13 on screen:
//   J = -(1 + e) v_ab.n / (1/m_a + 1/m_b + [(I_a^-1 (r_a x n)) x r_a + (I_b^-1 (r_b x n)) x r_b].n)
struct ImpactNumbers {
  double time = -1;        // s: the step it happened in; < 0: none yet
  int body_a = -1, body_b = -1;
  double approach = 0;     // m/s: v_ab.n of the centres just before the step (negative while closing; n pushes a)
  double point_approach = 0;  // m/s: the same at the contact point, spins included (v + w x r, eq. 11)
  double restitution = 0;  // e of the pair
  double inverse_mass_a = 0, inverse_mass_b = 0;  // 1/kg (0: static)
  physics::Vec3 offset_a = physics::Vec3::Zero(), offset_b = physics::Vec3::Zero();  // m: r_a, r_b, centre to contact
  double angular = 0;      // 1/kg: eq. 13's angular term, [...].n above
  double impulse = 0;      // N s: what the solver gave, along n on a
};

// Whether a frame shows an impact's numbers ([overlay] equation, or an [[equation]] with live values).
bool shows_impact_numbers(const Scene& scene);

}  // namespace impulse::demos
