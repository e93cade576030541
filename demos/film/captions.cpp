#include "demos/film/captions.h"

#include <algorithm>

namespace impulse::demos {

float cue_opacity(double start, double end, double time) {
  constexpr double kFade = 0.2;  // s
  const double fade = std::min(kFade, 0.25 * (end - start));
  return float(std::clamp(std::min({1.0, (time - start) / fade + 0.25, (end - time) / fade}), 0.0, 1.0));
}

std::vector<render::Caption> captions_at(const std::vector<CaptionCue>& cues, double time) {
  std::vector<render::Caption> shown;
  for (const CaptionCue& cue : cues)
    if (time >= cue.start && time < cue.end) shown.push_back({cue.text, cue_opacity(cue.start, cue.end, time), cue.own ? 0 : -1});
  return shown;
}

}  // namespace impulse::demos
