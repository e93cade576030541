#include "demos/verify.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "render/image_compare.h"
#include "render/part_file.h"
#include "render/png_io.h"

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

// A scratch directory for the rendered frames, removed however verify ends.
struct Scratch {
  fs::path path = fs::temp_directory_path() / ("impulse_verify_" + std::to_string(getpid()));
  Scratch() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

}  // namespace

VerifyResult verify_scene(const Scene& scene, RenderOptions options, const VerifyOptions& verify) {
  const Scratch scratch;
  options.video_path.clear();
  options.png_directory = scratch.path.string();
  options.png_frames = verify.frames;
  options.png_spread = verify.frames.empty() ? 3 : 0;
  VerifyResult result;
  result.checks = render_scene(scene, options);

  std::vector<fs::path> rendered;
  for (const auto& entry : fs::directory_iterator(scratch.path)) rendered.push_back(entry.path());
  std::sort(rendered.begin(), rendered.end());
  if (rendered.empty()) {
    result.passed = false;
    result.lines.push_back("no frame was rendered: --frames names frames past the video's end");
  }
  const fs::path golden_directory = verify.golden_directory;
  if (verify.update) fs::create_directories(golden_directory);
  for (const fs::path& frame_path : rendered) {
    const fs::path golden = golden_directory / frame_path.filename();
    const render::Frame actual = render::read_png(frame_path.string());
    if (verify.update) {
      render::write_png(golden.string(), actual);
      result.lines.push_back("wrote " + golden.string());
      continue;
    }
    if (!fs::exists(golden)) {
      result.passed = false;
      result.lines.push_back("no golden " + golden.string() + " (run with --update to make it)");
      continue;
    }
    const render::Frame expected = render::read_png(golden.string());
    const render::ImageDifference difference = render::compare_images(expected, actual);
    const fs::path stem = golden_directory / frame_path.stem();
    if (difference.matches) {
      result.lines.push_back("matches " + golden.string() + " (" + difference.summary + ")");
      fs::remove(stem.string() + ".actual.png");
      fs::remove(stem.string() + ".diff.png");
      continue;
    }
    result.passed = false;
    render::write_png(stem.string() + ".actual.png", actual);
    if (difference.same_size) {
      render::write_png(stem.string() + ".diff.png", render::difference_image(expected, actual, render::ImageTolerance{}.pixel_threshold));
    }
    result.lines.push_back("DIFFERS from " + golden.string() + ": " + difference.summary + "; see " + stem.string() +
                           ".diff.png and .actual.png (--update makes the new look the golden)");
  }
  return result;
}

}  // namespace impulse::demos
