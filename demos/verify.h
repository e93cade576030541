// `impulse verify`: a course's visual regression check. Renders chosen frames of a scene and
// compares them with the PNGs of a golden directory by the tolerance of the project's own golden
// tests (render/image_compare.h); each frame that differs gets NAME.actual.png and NAME.diff.png
// (the differing pixels red) beside its golden, and the report says where it differs.
#pragma once
#include <string>
#include <vector>

#include "demos/film/render_scene.h"

namespace impulse::demos {

struct VerifyOptions {
  std::string golden_directory;
  std::vector<int> frames;  // empty: the first, the middle and the last
  bool update = false;      // write the goldens instead of comparing
};

struct VerifyResult {
  std::vector<std::string> lines;  // one per frame: matched, differs (and where), written, missing
  bool passed = true;
  std::vector<CheckResult> checks;  // the scene's [[check]]s, from the same run
};

// Throws render::OutputError when a file cannot be written.
VerifyResult verify_scene(const Scene& scene, RenderOptions options, const VerifyOptions& verify);

}  // namespace impulse::demos
