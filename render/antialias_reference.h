// What anti-aliasing is measured against: the frame drawn 16 times without anti-aliasing, each
// time moved by one offset of a 4x4 grid inside the pixel ((i + 1/2) / 4 - 1/2 pixels in x and
// in y), and averaged: a 16x supersampled image, box-filtered, at the frame's own size (so what
// is sized in pixels, such as arrows' least widths and the ground's grid lines, is as in the frame).
// Averaged as stored (sRGB-like values), as a multisample resolve averages.
#pragma once
#include "render/draw_list.h"
#include "render/frame.h"
#include "render/renderer.h"

namespace impulse::render {

// `settings`' anti-aliasing is ignored (none is used); the rest (shadows, spheres) is kept.
// `grid` offsets a side: 4 gives the 16x reference; 8 (64x) is nearer the true coverage. (4x MSAA's
// four samples lie in four of the 4x4 grid's columns and rows, so along near-vertical and
// near-horizontal edges it steps as the 16x reference does.)
Frame supersampled_reference(int width, int height, RendererSettings settings, const DrawList& draw_list, int grid = 4);

// Mean over every pixel and R, G, B of |a - b|, in 0..255. Throws std::invalid_argument if the
// sizes differ.
double mean_colour_error(const Frame& a, const Frame& b);

}  // namespace impulse::render
