// --layout-report FILE.json: where each video frame's overlay put its elements and where each
// pane's bodies were, for tests and for a lecturer checking a scene's frames without looking:
//
//   {"width": 854, "height": 480, "frames": [
//     {"frame": 0, "elements": [{"name": "title", "x": 13, "y": 13, "w": 401, "h": 49}, ...],
//      "dropped": [], "bodies": [{"pane": 0, "name": "ball", "moving": true, "x": 380, ...}, ...]},
//     ...]}
//
// Boxes are whole pixels covering what was painted (x, y rounded down, the far edges up); an
// element left out for want of room is named in "dropped". Frames are written as they are
// finished into the report's own temporary, renamed into place by commit() (render/part_file.h):
// the report is complete or absent.
#pragma once
#include "render/overlay.h"
#include "render/overlay_painter.h"
#include "render/part_file.h"

#include <fstream>
#include <string>
#include <vector>

namespace impulse::demos {

class LayoutReport {
 public:
  // Throws render::OutputError if `path` cannot be written.
  LayoutReport(const std::string& path, int width, int height);
  void add(int frame, const render::PaintedLayout& layout, const std::vector<render::OverlayBody>& bodies);
  void commit();  // throws render::OutputError naming the file

 private:
  render::PartFile part_;
  std::ofstream file_;
  bool first_frame_ = true;
};

}  // namespace impulse::demos
