// The benchmark's frame (tests/bench): 300 spheres, 100 boxes and 400 arrows on a ground, as a
// DrawList, plus an overlay of the kind a lecture video carries. Deterministic: no random library
// (its distributions differ between standard libraries), a fixed integer hash instead.
#pragma once
#include "render/draw_list.h"
#include "render/overlay.h"

namespace impulse::bench {

// The scene at time `t` seconds: bodies bob and arrows swing a little so frames differ (as in a
// real video, where the encoder cannot just repeat the previous frame).
render::DrawList bench_draw_list(double t);
render::Overlay bench_overlay(double t, double duration);

}  // namespace impulse::bench
