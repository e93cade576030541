// What anti-aliasing is measured against: the frame drawn 16 times without anti-aliasing, each
// time moved by a sub-pixel offset, and averaged: a 16x supersampled image, box-filtered, at the
// frame's own size (so what is sized in pixels, such as arrows' least widths and the ground's grid
// lines, is as in the frame). The offsets are jittered: one at a fixed pseudo-random place in
// each cell of a 4x4 grid over the pixel. (Not the cells' centres: 4x MSAA's four samples, at
// (+-1/8, +-3/8) and (+-3/8, -+1/8) pixels, are four of those sixteen centres, so an ordered grid
// shares a quarter of its samples with it and favours it.) Averaged as stored (sRGB-like
// values), as a multisample resolve averages.
#pragma once
#include "render/draw_list.h"
#include "render/frame.h"
#include "render/renderer.h"

namespace impulse::render {

// `settings`' anti-aliasing is ignored (none is used); the rest (shadows, spheres) is kept.
// `grid` cells a side: 4 gives the 16x reference; 8 (64x) is nearer the true coverage.
Frame supersampled_reference(int width, int height, RendererSettings settings, const DrawList& draw_list, int grid = 4);

// Mean over every pixel and R, G, B of |a - b|, in 0..255. Throws std::invalid_argument if the
// sizes differ.
double mean_colour_error(const Frame& a, const Frame& b);

}  // namespace impulse::render
