// Two frames compared as pixelmatch compares screenshots (mapbox/pixelmatch, what Playwright's
// screenshot tests use), written here in C++:
// - a pixel differs when its perceptual colour distance (in YIQ, the NTSC colour space; 0 same,
//   1 the farthest two colours can be, black against white 0.97) is above `colour_threshold`, and it is not an anti-aliased edge pixel
//   (a pixel between a darker and a brighter neighbour of which one is flat in both frames: an edge
//   drawn a hair to the side, as llvmpipe's vector widths and CPUs do);
// - the frames differ when the differing pixels touching each other (8 neighbours) form a region
//   of more than `max_region_pixels`, or when more than `max_differing_share` of all pixels differ;
// - or when the pixels over the fainter `faint_threshold` (the differing ones among them) form a
//   region of more than `max_faint_region_pixels`: a change too faint to see in a few pixels is
//   plain over an area, as the eye sums contrast over area. A sleeping body is drawn pale (its
//   colour mixed towards grey and white), which shrinks a recolouring's distance below
//   `colour_threshold` on its shaded faces (green to vermillion: 0.09 on a box's front face, 0.13
//   on its lit top), yet a person sees the whole body change.
// A small body that changes colour, moves or vanishes is one region however large the frame is.
// The defaults are measured: README.md, "verify", has the table. `impulse verify` and the
// project's golden tests (tests/support/golden_image.h) both use them.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/frame.h"

namespace impulse::render {

struct ImageTolerance {
  double colour_threshold = 0.1;         // YIQ distance, 0..1, as pixelmatch's `threshold`
  int max_region_pixels = 12;            // the largest connected region of differing pixels allowed
  double max_differing_share = 0.0005;   // 0.05 % of the frame in all
  double faint_threshold = 0.05;         // YIQ distance of a faint difference
  int max_faint_region_pixels = 100;     // the largest connected region of faint (or differing) pixels allowed
};

// What each pixel of the compared area is: faint is over the faint threshold, under the colour one.
enum class PixelVerdict : uint8_t { same, anti_aliased, faint, differs };

// A connected region of pixels (8 neighbours) and the box around it.
struct PixelRegion {
  int pixels = 0;
  int left = 0, top = 0, right = -1, bottom = -1;
};

struct ImageDifference {
  bool same_size = false;
  bool matches = false;
  int differing_pixels = 0;     // not counting anti-aliased ones
  int anti_aliased_pixels = 0;  // above the threshold, but an edge a hair to the side
  double differing_share = 0;   // of the pixels
  int largest_region = 0;       // pixels in the largest connected region of differing pixels
  int left = 0, top = 0, right = -1, bottom = -1;  // the box around that region (pixels)
  int faint_pixels = 0;         // faint, not counting anti-aliased ones
  PixelRegion largest_faint_region;  // of faint and differing pixels together
  std::vector<PixelVerdict> verdicts;  // row by row over the smaller of the two sizes
  int width = 0, height = 0;           // of `verdicts`
  std::string summary;  // "a region of 340 pixels differs (allowed: 12), in x 410..440, y 200..228; 0.08 % of the frame"
};

ImageDifference compare_images(const Frame& expected, const Frame& actual, ImageTolerance tolerance = {});

// YIQ distance of two RGB colours, 0 (same) .. 1 (the farthest two can be; black and white: 0.97).
double colour_distance(const uint8_t* a, const uint8_t* b);

// The larger of the two frames' sizes: `expected` faded towards white, differing pixels red,
// faint ones pink, anti-aliased ones yellow, and where only one frame has pixels (sizes differ)
// magenta.
Frame difference_image(const Frame& expected, const Frame& actual, const ImageDifference& difference);

// Frames side by side, left to right, top-aligned on a grey ground, 8 pixels apart (golden |
// actual | diff).
Frame side_by_side(const std::vector<const Frame*>& frames);

}  // namespace impulse::render
