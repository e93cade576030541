// DIR/report.html of `impulse verify`: one page a CI job keeps as an artefact, with what was
// compared (the manifest), each moment's verdict and lines, and its golden | actual | diff strip.
#pragma once
#include <string>
#include <vector>

#include "demos/golden_manifest.h"

namespace impulse::demos {

struct MomentReport {
  double time = 0;  // simulated s
  bool passed = true;
  std::vector<std::string> lines;           // what was found
  std::string golden, actual, diff, strip;  // paths of the images; empty: none
};

// `notes`: said above the moments (that the sizes differ, that --set differs). Throws
// render::OutputError when the file cannot be written.
void write_report(const std::string& path, const std::string& scene_path, const GoldenManifest& manifest, bool passed,
                  const std::vector<std::string>& notes, const std::vector<MomentReport>& moments);

}  // namespace impulse::demos
