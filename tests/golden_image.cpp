#include "tests/golden_image.h"

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

GoldenResult compare_with_golden(const std::string& name, const render::Frame& actual, GoldenTolerance tolerance) {
  const fs::path golden_path = kGoldenDirectory / (name + ".png");
  if (updating()) {
    fs::create_directories(kGoldenDirectory);
    render::write_png(golden_path.string(), actual);
    return {true, "updated " + golden_path.string()};
  }
  const fs::path actual_path = kFailureDirectory / (name + ".actual.png");
  auto keep_actual = [&] {
    fs::create_directories(kFailureDirectory);
    render::write_png(actual_path.string(), actual);
  };
  if (!fs::exists(golden_path)) {
    keep_actual();
    return {false, "no golden image " + golden_path.string() + " (the render is in " + actual_path.string() +
                       "; look at it, then IMPULSE_UPDATE_GOLDEN=1 to make it the golden)"};
  }
  const render::Frame golden = render::read_png(golden_path.string());
  if (golden.width != actual.width || golden.height != actual.height) {
    keep_actual();
    return {false, golden_path.string() + " is " + std::to_string(golden.width) + "x" + std::to_string(golden.height) +
                       " but the render is " + std::to_string(actual.width) + "x" + std::to_string(actual.height)};
  }
  const render::ImageDifference difference = render::compare_images(golden, actual, tolerance);
  if (difference.matches) return {true, ""};

  keep_actual();
  const fs::path diff_path = kFailureDirectory / (name + ".diff.png");
  render::write_png(diff_path.string(), render::difference_image(golden, actual, tolerance.pixel_threshold));
  return {false, "golden " + name + ": " + difference.summary + "; see " + fs::absolute(diff_path).string() + " and " +
                     fs::absolute(actual_path).string() + " (if the new look is meant, IMPULSE_UPDATE_GOLDEN=1 ctest -R Golden)"};
}

}  // namespace impulse::testing
