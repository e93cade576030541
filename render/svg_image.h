// An SVG (typeset mathematics: filled paths, as dvisvgm --no-fonts writes them) rasterised by
// librsvg into a cairo image, to be painted as a mask in any ink colour. Including this needs
// cairo's headers: link PkgConfig::CAIRO.
#pragma once
#include "render/cairo_handles.h"

#include <string>

namespace impulse::render {

struct SvgRaster {
  cairo::SurfaceHandle surface;  // ARGB32: the SVG's coverage in its alpha, transparent around
  int width = 0, height = 0;     // pixels
};

// Draws `svg` at `pixels_per_point` pixels per unit of its size (points, for dvisvgm's SVGs; a
// pixel of transparent margin all round so anti-aliased edges are whole). `embolden` (units)
// strokes every path that much wider: Computer Modern's hairlines are thinner than a pixel at
// video sizes and would read pale grey. Throws std::runtime_error when librsvg cannot read it.
SvgRaster rasterise_svg(const std::string& svg, double pixels_per_point, double embolden = 0);

}  // namespace impulse::render
