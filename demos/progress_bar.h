// A progress bar on stderr for renders longer than a second:
//   bounce.toml [#########...........]  81/180 frames  31.2 frames/s  3 s left
// On a terminal it is redrawn at most ten times a second on one line; into a file or pipe (asked
// for with --progress) it writes a line every five seconds. finish() ends it. Silent when disabled.
#pragma once
#include <chrono>
#include <cstdio>
#include <string>

namespace impulse::demos {

class ProgressBar {
 public:
  ProgressBar(bool enabled, std::string label, std::FILE* stream = stderr);
  void update(int frames_done, int total_frames);
  void finish();

 private:
  void draw(int frames_done, double seconds);

  bool enabled_;
  std::string label_;
  int total_ = 1;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_draw_ = -1.0;
  bool drawn_ = false;
  bool terminal_ = false;
};

}  // namespace impulse::demos
