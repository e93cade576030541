// Paints an Overlay (overlay.h) over a Frame with cairo: text in DejaVu Sans, anti-aliased lines.
// Sizes follow the frame's height (a 480p and a 1080p video look alike). Every element is measured
// first, then laid out (overlay_layout.h: never over another, never outside the frame, over
// bodies only when no free place is left), then painted where the layout put it. One painter per
// thread.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "render/frame.h"
#include "render/overlay.h"

namespace impulse::render {

// Where the last paint() put each element of the overlay (overlay_layout.h places them): its
// name ("title", "clock", "caption 1", "legend", "plot 2", "panel 1", "pane label 3", "label 1")
// and its box, in the order placed; and the elements left out because no place was left.
struct PaintedElement {
  std::string name;
  ScreenBox box;
};
// A label placed away from its anchor is joined to it by a leader line, drawn under everything.
struct PaintedLeader {
  int label = -1;     // index into Overlay::labels
  Vec2f from, to;     // from the anchor to the nearest point of the label's box
};
struct PaintedLayout {
  std::vector<PaintedElement> elements;
  std::vector<std::string> dropped;
  std::vector<PaintedLeader> leaders;
};

class OverlayPainter {
 public:
  // Throws std::runtime_error if cairo cannot make its image surface.
  OverlayPainter(int width, int height);
  ~OverlayPainter();
  OverlayPainter(const OverlayPainter&) = delete;
  OverlayPainter& operator=(const OverlayPainter&) = delete;

  // Draws `overlay` onto `frame` (its size must be the painter's; else std::invalid_argument).
  void paint(const Overlay& overlay, Frame& frame);
  // What the last paint() placed where.
  const PaintedLayout& layout() const;

 private:
  struct Cairo;  // the surface and context, kept out of this header
  std::unique_ptr<Cairo> cairo_;
};

}  // namespace impulse::render
