// Anti-aliasing after a single-sampled draw, from where the outlines are (geometric anti-aliasing,
// after Humus's GBAA): beside its colour, every fragment writes how far its pixel's centre is from
// the nearest outline of what it drew towards +x, -x, +y and -y, in pixels, each outline counted
// along the axis it is more across (shaders.cpp, `with_edge`). Then each pixel takes in, from the
// neighbour in each direction:
// - its own outline that way crossing it (distance d < 1/2): the part 1/2 - d beyond it;
// - else the neighbour's outline towards it reaching into it (1/2 <= d < 1): the part d - 1/2.
// For a straight outline with a slope up to 1 across the axis, that part is exactly the pixel's
// area beyond the outline, so a long edge gets its true coverage (4x MSAA: to a quarter at best),
// a part thinner than a pixel takes in both sides, and a right-angled corner (outlines across x
// and across y) its part beyond both once. Curved corners and outlines closer than a pixel to one
// another keep some error; tests/bench/render_bench measures it.
#pragma once
#include <cstdint>

#include "render/frame.h"

namespace impulse::render {

// An edge image has 4 bytes a pixel, the directions +x, -x, +y, -y (bottom-up, as GL), each
// 255 * (1 - distance): 0 is no outline within a pixel that way.
constexpr uint8_t kNoEdge = 0;
inline float edge_distance(uint8_t stored) { return 1.0f - float(stored) * (1.0f / 255.0f); }

// `colour` (RGBA) and `edges` (as above) are bottom-up images as glReadPixels gives them;
// `frame` gets the anti-aliased image, rows top to bottom (resized to width x height).
void resolve_edges(const uint8_t* colour, const uint8_t* edges, int width, int height, Frame& frame);

}  // namespace impulse::render
