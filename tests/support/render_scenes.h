// Fixed draw lists and overlays (no physics, no scene file) shared by the golden tests and the
// child program that draws every shader program (render_every_program.cpp).
#pragma once
#include "render/draw_list.h"
#include "render/overlay.h"

namespace impulse::testing {

// A sphere in the air (its shadow below), a sleeping sphere and box on the ground, a tilted box,
// contact points and overlapping arrows of every kind.
render::DrawList bodies_scene();

// A title, a caption, the clock, the playback line, a legend, a value label and a plot.
render::Overlay lecture_overlay();

}  // namespace impulse::testing
