#include "demos/progress_bar.h"

#include <algorithm>

#include <unistd.h>

namespace impulse::demos {

ProgressBar::ProgressBar(bool enabled, std::string label, std::FILE* stream)
    : enabled_(enabled),
      label_(std::move(label)),
      stream_(stream),
      terminal_(isatty(fileno(stream)) != 0) {}

void ProgressBar::update(int frames_done, int total_frames) {
  if (!enabled_) return;
  total_ = std::max(total_frames, 1);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (seconds < 1.0 || seconds - last_draw_ < (terminal_ ? 0.1 : 5.0)) return;  // short renders stay quiet
  draw(frames_done, seconds);
}

void ProgressBar::draw(int frames_done, double seconds) {
  constexpr int kWidth = 24;
  const double fraction = std::clamp(double(frames_done) / total_, 0.0, 1.0);
  const int filled = int(fraction * kWidth);
  const double rate = frames_done / std::max(seconds, 1e-6);
  const double left = rate > 0 ? (total_ - frames_done) / rate : 0;
  std::string bar(size_t(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stream_, "%s%s [%s] %d/%d frames  %.1f frames/s  %.0f s left%s", terminal_ ? "\r" : "", label_.c_str(),
               bar.c_str(), frames_done, total_, rate, left, terminal_ ? " " : "\n");
  std::fflush(stream_);
  last_draw_ = seconds;
  drawn_ = true;
}

void ProgressBar::finish() {
  if (!enabled_ || !drawn_) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  draw(total_, seconds);
  if (terminal_) std::fputc('\n', stream_);
  drawn_ = false;
}

}  // namespace impulse::demos
