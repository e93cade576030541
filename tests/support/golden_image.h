// Golden-image checks with the comparison `impulse verify` uses (render/image_compare.h: perceptual
// colour distance, anti-aliased edges forgiven, connected regions of differing pixels).
//
// Goldens live in assets/golden/NAME.png. On a failure the actual image, a diff image (differing
// pixels red over a faded golden) and a golden | actual | diff strip go to out/golden/, and the
// message says where. IMPULSE_UPDATE_GOLDEN=1 rewrites the goldens from the actual images instead,
// and the test is then skipped, saying so: no test passes without comparing (render/README.md,
// "Golden images").
#pragma once
#include <string>

#include "render/frame.h"
#include "render/image_compare.h"

namespace impulse::testing {

using GoldenTolerance = render::ImageTolerance;  // render/image_compare.h

struct GoldenResult {
  bool passed = false;
  bool updated = false;  // IMPULSE_UPDATE_GOLDEN=1: written, not compared
  std::string message;   // why not, and where the images are; or what was written
};

// `name` without extension. Paths are relative to the repository root (the tests' working directory).
GoldenResult compare_with_golden(const std::string& name, const render::Frame& actual, GoldenTolerance tolerance = {});

// Pins llvmpipe's vector width (LP_NATIVE_VECTOR_WIDTH=128) so that every x86-64 machine renders
// the same bytes. Must run before the first GL context exists; the golden tests call it from a
// static initialiser.
void pin_llvmpipe_for_goldens();
bool llvmpipe_pinned();  // LP_NATIVE_VECTOR_WIDTH is 128 in this process

// For a test's body: fails with the message, skips (saying what it wrote) when updating.
#define EXPECT_MATCHES_GOLDEN(name, frame)                                          \
  do {                                                                              \
    const ::impulse::testing::GoldenResult golden_result =                          \
        ::impulse::testing::compare_with_golden(name, frame);                       \
    if (golden_result.updated) GTEST_SKIP() << golden_result.message;               \
    EXPECT_TRUE(golden_result.passed) << golden_result.message;                     \
  } while (false)

}  // namespace impulse::testing
