#include "render/offscreen_target.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>


namespace impulse::render {
namespace {

// Checks the framebuffer bound to GL_FRAMEBUFFER.
void require_complete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char message[96];
    std::snprintf(message, sizeof message, "OpenGL: %s framebuffer is incomplete (status 0x%04X)", what, status);
    throw std::runtime_error(message);
  }
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples, bool edges)
    : width_(width), height_(height), samples_(samples), edges_(edges) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width <= 0 || height <= 0 || width > max_size || height > max_size) {
    throw std::runtime_error("renderer: frame size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is outside 1.." + std::to_string(max_size));
  }
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(samples, 0, static_cast<int>(max_samples));
  if (edges_ && samples_ > 0) throw std::logic_error("OffscreenTarget: edge anti-aliasing draws one sample a pixel");

  auto storage = [&](const GlRenderbuffer& renderbuffer, int sample_count, GLenum internal_format) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer.id());
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, sample_count, internal_format, width, height);
  };
  storage(multisample_colour_, samples_, GL_RGBA8);
  storage(multisample_depth_, samples_, GL_DEPTH_COMPONENT24);
  if (samples_ > 0) storage(resolved_colour_, 0, GL_RGBA8);
  if (edges_) storage(edge_image_, 0, GL_RGBA8);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  glBindFramebuffer(GL_FRAMEBUFFER, multisample_framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, multisample_colour_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, multisample_depth_.id());
  if (edges_) {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, edge_image_.id());
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, both);
  }
  require_complete("main");

  if (samples_ > 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, resolved_framebuffer_.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolved_colour_.id());
    require_complete("resolve");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void OffscreenTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, multisample_framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

void OffscreenTarget::copy_samples_to(const OffscreenTarget& other) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisample_framebuffer_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, other.multisample_framebuffer_.id());
  if (other.edges_) glDrawBuffer(GL_COLOR_ATTACHMENT0);  // a blit writes every draw buffer
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                    GL_NEAREST);
  if (other.edges_) {
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, both);
    other.clear_edges();
  }
}

void OffscreenTarget::clear_edges() const {
  if (!edges_) return;
  const GLfloat none[4] = {0, 0, 0, 0};  // kNoEdge
  glClearBufferfv(GL_COLOR, 1, none);
}

void OffscreenTarget::read_into(ReadBack& read_back) const {
  if (samples_ > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisample_framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_framebuffer_.id());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_framebuffer_.id());
  } else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisample_framebuffer_.id());  // one sample: read it as drawn
  }
  read_back.width = width_;
  read_back.height = height_;
  const size_t bytes = static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4;
  read_back.bottom_up_rgba.resize(bytes);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, read_back.bottom_up_rgba.data());
  if (!edges_) {
    read_back.bottom_up_edges.clear();
    return;
  }
  read_back.bottom_up_edges.resize(bytes);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, read_back.bottom_up_edges.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
}

}  // namespace impulse::render
