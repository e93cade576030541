// Where the main pass draws: a colour + depth framebuffer, multisampled and then resolved into a
// single-sample one, or single-sampled and read back as it is; with `edges`, a second colour
// image (RGBA8) where each pixel's nearest outlines are, read back beside the colours for the CPU
// to anti-alias them with (read_back.h, edge_antialias.h).
#pragma once
#include "render/read_back.h"
#include "render/gl_objects.h"

namespace impulse::render {

class OffscreenTarget {
 public:
  // Throws std::runtime_error if incomplete. `edges` needs samples == 0.
  OffscreenTarget(int width, int height, int samples, bool edges = false);

  void bind_for_drawing() const;  // binds the draw framebuffer and sets the viewport
  // Copies this target's colour and depth samples into `other` (same size and samples); `other`'s
  // edge image, if any, is cleared (no outline anywhere).
  void copy_samples_to(const OffscreenTarget& other) const;
  void clear_edges() const;  // with the draw framebuffer bound
  // Resolves the samples (if any) and reads the colours back, and the edge image if there is one.
  void read_into(ReadBack& read_back) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  int width_;
  int height_;
  int samples_;
  bool edges_;
  GlRenderbuffer multisample_colour_;
  GlRenderbuffer multisample_depth_;
  GlRenderbuffer edge_image_;
  GlFramebuffer multisample_framebuffer_;
  GlRenderbuffer resolved_colour_;
  GlFramebuffer resolved_framebuffer_;
};

}  // namespace impulse::render
