#include "tests/golden_image.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

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

// The golden faded towards white, with the differing pixels in red.
render::Frame diff_image(const render::Frame& golden, const render::Frame& actual, int threshold) {
  render::Frame diff = golden;
  for (size_t i = 0; i < diff.rgba.size(); i += 4) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) differs |= std::abs(int(golden.rgba[i + c]) - int(actual.rgba[i + c])) > threshold;
    for (int c = 0; c < 3; ++c) diff.rgba[i + c] = differs ? (c == 0 ? 255 : 0) : uint8_t(191 + golden.rgba[i + c] / 4);
    diff.rgba[i + 3] = 255;
  }
  return diff;
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
  size_t differing = 0;
  for (size_t i = 0; i < golden.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(int(golden.rgba[i + c]) - int(actual.rgba[i + c])) > tolerance.pixel_threshold) {
        ++differing;
        break;
      }
    }
  }
  const double share = double(differing) / double(golden.rgba.size() / 4);
  if (share <= tolerance.max_differing_share) return {true, ""};

  keep_actual();
  const fs::path diff_path = kFailureDirectory / (name + ".diff.png");
  render::write_png(diff_path.string(), diff_image(golden, actual, tolerance.pixel_threshold));
  char summary[160];
  std::snprintf(summary, sizeof summary, "%.2f %% of the pixels differ by more than %d (allowed: %.2f %%)", 100 * share,
                tolerance.pixel_threshold, 100 * tolerance.max_differing_share);
  return {false, "golden " + name + ": " + summary + "; see " + fs::absolute(diff_path).string() + " and " +
                     fs::absolute(actual_path).string() + " (if the new look is meant, IMPULSE_UPDATE_GOLDEN=1 ctest -R Golden)"};
}

}  // namespace impulse::testing
