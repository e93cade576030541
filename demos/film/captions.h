// The captions a frame shows: each [[caption]] from its start to its end (simulated seconds),
// fading in and out over the first and last 0.2 s of its time cue.
#pragma once
#include "demos/scene/view_options.h"
#include "render/overlay.h"

#include <vector>

namespace impulse::demos {

// A pane's own cue (CaptionCue::own) is given pane 0: the film puts each pane's in its place.
std::vector<render::Caption> captions_at(const std::vector<CaptionCue>& cues, double time);

// How opaque a cue shown from `start` to `end` is at `time` within it: fading in and out over
// 0.2 s (a quarter of a shorter cue). Captions and [[equation]]s fade alike.
float cue_opacity(double start, double end, double time);

}  // namespace impulse::demos
