// Paints an Overlay (overlay.h) over a Frame with cairo: text in DejaVu Sans, anti-aliased lines.
// Sizes follow the frame's height (a 480p and a 1080p video look alike). One painter per thread.
#pragma once
#include <memory>

#include "render/frame.h"
#include "render/overlay.h"

namespace impulse::render {

class OverlayPainter {
 public:
  // Throws std::runtime_error if cairo cannot make its image surface.
  OverlayPainter(int width, int height);
  ~OverlayPainter();
  OverlayPainter(const OverlayPainter&) = delete;
  OverlayPainter& operator=(const OverlayPainter&) = delete;

  // Draws `overlay` onto `frame` (its size must be the painter's; else std::invalid_argument).
  void paint(const Overlay& overlay, Frame& frame);

 private:
  struct Cairo;  // the surface and context, kept out of this header
  std::unique_ptr<Cairo> cairo_;
};

}  // namespace impulse::render
