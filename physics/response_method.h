// The workshop's ways of answering a collision, selectable per scene for side-by-side teaching.
#pragma once
#include <array>
#include <optional>
#include <string_view>

namespace impulse::physics {

enum class ResponseMethod {
  impulse,     // sequential impulses done properly (the default): accumulated, clamped, warm started, soft
  workshop,    // listing 1 as printed: one impulse per contact per step, the 1.5 x penetration "hack fix"
  projection,  // section 1: move the bodies apart by the penetration, velocities untouched
  penalty,     // section 1: spring-damper forces from the penetration
};

std::string_view method_name(ResponseMethod method);
const std::array<std::string_view, 4>& method_names();  // as scene files spell them
std::optional<ResponseMethod> method_from_name(std::string_view name);

// Spring-damper contact forces of the penalty method, per contact, as a frequency and damping
// ratio of the contact's effective mass: k = m w^2, c = 2 zeta m w, with w = 2 pi hertz.
struct PenaltySettings {
  double hertz = 30;
  double damping_ratio = 0.3;
};

}  // namespace impulse::physics
