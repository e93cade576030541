// Arrows (and lines) as flat shapes, the way a lecture figure draws them: a shaft quad and a head triangle
// lying along the arrow and turned to face the camera. Three triangles per arrow, built on the
// CPU into one vertex list, so 400 arrows cost one small draw call (llvmpipe pays dearly for
// many small multisampled triangles, which round 3D arrows would need).
#pragma once
#include <vector>

#include "render/camera_view.h"
#include "render/draw_list.h"
#include "render/overlay.h"

namespace impulse::render {

struct FlatVertex {
  float position[3];
  float colour[3];  // sRGB
  // Four values that are 0 along the shape's outline and positive inside, interpolated across the
  // shape (for edge anti-aliasing): a quad's sides and ends, not its diagonal; 2 where unused.
  float outline[4];
};

// Head and shaft grow with the arrow's length up to a limit, so short arrows stay arrows and long
// ones stay slim, and never get thinner on screen than a few pixels (they stay legible far away).
// Arrows shorter than 1e-5 m, or behind the camera, add nothing.
void append_flat_arrow(const ArrowItem& arrow, const CameraView& camera, std::vector<FlatVertex>& triangles);

// The arrow's outline on screen, as append_flat_arrow draws it: its centre line, the shaft's two
// sides and the head's three, for an overlay label that must not cover it.
void append_flat_arrow_outline(const ArrowItem& arrow, const CameraView& camera, std::vector<ScreenSegment>& outline);

// A line as a camera-facing strip `width_pixels` wide (two triangles).
void append_flat_line(const LineItem& line, const CameraView& camera, std::vector<FlatVertex>& triangles);

}  // namespace impulse::render
