#include "tests/support/golden_image.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "render/image_compare.h"
#include "render/png_io.h"

namespace impulse::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kGoldenDirectory = "assets/golden";
const fs::path kFailureDirectory = "out/golden";

bool updating() {
  const char* update = std::getenv("IMPULSE_UPDATE_GOLDEN");
  return update != nullptr && std::string(update) == "1";
}

}  // namespace

void pin_llvmpipe_for_goldens() { setenv("LP_NATIVE_VECTOR_WIDTH", "128", 1); }

bool llvmpipe_pinned() {
  const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH");
  return width != nullptr && std::string(width) == "128";
}

GoldenResult compare_with_golden(const std::string& name, const render::Frame& actual, GoldenTolerance tolerance) {
  const fs::path golden_path = kGoldenDirectory / (name + ".png");
  if (updating()) {
    fs::create_directories(kGoldenDirectory);
    render::write_png(golden_path.string(), actual);
    return {false, true, "IMPULSE_UPDATE_GOLDEN=1: wrote " + golden_path.string() +
                             " without comparing; look at it, then run the test without IMPULSE_UPDATE_GOLDEN"};
  }
  const fs::path actual_path = kFailureDirectory / (name + ".actual.png");
  auto keep_actual = [&] {
    fs::create_directories(kFailureDirectory);
    render::write_png(actual_path.string(), actual);
  };
  if (!fs::exists(golden_path)) {
    keep_actual();
    return {false, false, "no golden image " + golden_path.string() + " (the render is in " + actual_path.string() +
                       "; look at it, then IMPULSE_UPDATE_GOLDEN=1 to make it the golden)"};
  }
  const render::Frame golden = render::read_png(golden_path.string());
  const render::ImageDifference difference = render::compare_images(golden, actual, tolerance);
  if (difference.matches) return {true, false, ""};

  keep_actual();
  const fs::path diff_path = kFailureDirectory / (name + ".diff.png");
  const fs::path strip_path = kFailureDirectory / (name + ".strip.png");
  const render::Frame diff = render::difference_image(golden, actual, difference);
  render::write_png(diff_path.string(), diff);
  render::write_png(strip_path.string(), render::side_by_side({&golden, &actual, &diff}));
  return {false, false, "golden " + golden_path.string() + ": " + difference.summary + "; see " +
                            fs::absolute(strip_path).string() + " (golden | actual | diff; if the new look is meant, "
                            "IMPULSE_UPDATE_GOLDEN=1 ctest -R Golden, then look at the goldens)"};
}

}  // namespace impulse::testing
