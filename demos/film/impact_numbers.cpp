#include "demos/film/impact_numbers.h"

namespace impulse::demos {

bool shows_impact_numbers(const Scene& scene) {
  if (scene.overlay.equation != "none") return true;
  for (const EquationCue& cue : scene.equations)
    if (cue.live) return true;
  return false;
}

}  // namespace impulse::demos
