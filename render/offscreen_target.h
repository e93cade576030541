// Where the main pass draws: a multisampled colour + depth framebuffer, resolved into a
// single-sample one that is read back into a Frame.
#pragma once
#include <cstdint>
#include <vector>

#include "render/frame.h"
#include "render/gl_objects.h"

namespace impulse::render {

class OffscreenTarget {
 public:
  OffscreenTarget(int width, int height, int samples);  // throws std::runtime_error if incomplete

  void bind_for_drawing() const;  // binds the draw framebuffer and sets the viewport
  // Copies this target's colour and depth samples into `other` (same size and samples).
  void copy_samples_to(const OffscreenTarget& other) const;
  void resolve_into(Frame& frame);  // resolves the samples and reads RGBA, rows top to bottom

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  int width_;
  int height_;
  int samples_;
  GlRenderbuffer multisample_colour_;
  GlRenderbuffer multisample_depth_;
  GlFramebuffer multisample_framebuffer_;
  GlRenderbuffer resolved_colour_;
  GlFramebuffer resolved_framebuffer_;
  std::vector<uint8_t> bottom_up_pixels_;
};

}  // namespace impulse::render
