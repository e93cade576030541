#include "demos/film/captions.h"

#include <algorithm>

namespace impulse::demos {

std::vector<render::Caption> captions_at(const std::vector<CaptionCue>& cues, double time) {
  constexpr double kFade = 0.2;  // s
  std::vector<render::Caption> shown;
  for (const CaptionCue& cue : cues) {
    if (time < cue.start || time >= cue.end) continue;
    const double fade = std::min(kFade, 0.25 * (cue.end - cue.start));
    const double opacity = std::min({1.0, (time - cue.start) / fade + 0.25, (cue.end - time) / fade});
    shown.push_back({cue.text, float(std::clamp(opacity, 0.0, 1.0))});
  }
  return shown;
}

}  // namespace impulse::demos
