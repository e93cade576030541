// Golden-image checks, as three.js's and Blender's render tests do them: a pixel differs when one
// of its channels is more than `pixel_threshold` (0..255) away from the golden image, and the
// check passes while at most `max_differing_share` of the pixels differ.
//
// Goldens live in assets/golden/NAME.png. On a failure the actual image and a diff image (the
// differing pixels red over a faded golden) go to out/golden/, and the message says where.
// IMPULSE_UPDATE_GOLDEN=1 rewrites the goldens from the actual images instead (render/README.md, "Golden images").
#pragma once
#include <string>

#include "render/frame.h"
#include "render/image_compare.h"

namespace impulse::testing {

using GoldenTolerance = render::ImageTolerance;  // render/image_compare.h

struct GoldenResult {
  bool passed = false;
  std::string message;  // why not, and where the images are
};

// `name` without extension. Paths are relative to the repository root (the tests' working directory).
GoldenResult compare_with_golden(const std::string& name, const render::Frame& actual, GoldenTolerance tolerance = {});

// Pins llvmpipe's vector width (LP_NATIVE_VECTOR_WIDTH=128) so that every x86-64 machine renders
// the same bytes. Must run before the first GL context exists; the golden tests call it from a
// static initialiser.
void pin_llvmpipe_for_goldens();

}  // namespace impulse::testing
