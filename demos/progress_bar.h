// A progress bar on stderr for renders longer than a second:
//   bounce.toml [#########...........]  81/180 frames  31.2 frames/s  3 s left
// Redrawn at most ten times a second on one line; finish() ends the line. Silent when disabled.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace impulse::demos {

class ProgressBar {
 public:
  ProgressBar(bool enabled, std::string label, int total_frames, std::FILE* stream = stderr);
  void update(int frames_done);
  void finish();

 private:
  void draw(int frames_done, double seconds);

  bool enabled_;
  std::string label_;
  int total_;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_draw_ = -1.0;
  bool drawn_ = false;
};

}  // namespace impulse::demos
