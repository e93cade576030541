// The phases render_bench times, each on the benchmark frame (bench_frame.h): drawing alone,
// the overlay alone, encoding alone, the whole path to an MP4 as impulse does it, and the naive
// peer (a PNG file per frame, then the ffmpeg program over them).
#pragma once
#include <string>

#include "render/renderer.h"
#include "render/video_encoder.h"

namespace impulse::bench {

struct Timing {
  int frames = 0;
  double wall_seconds = 0;
  double cpu_seconds = 0;  // this process's threads, plus waited-for children (the ffmpeg program)
  double frames_per_second() const { return wall_seconds > 0 ? frames / wall_seconds : 0; }
};

struct BenchSettings {
  int width = 1280;
  int height = 720;
  int fps = 30;
  render::RendererSettings renderer;
  render::VideoSettings video() const;
};

Timing time_drawing(const BenchSettings& settings, int frames);
// The mean colour error (0..255 a channel) of the benchmark's first frame drawn with `settings`
// against its 16x and its 64x supersampled references (render/antialias_reference.h) drawn with
// the same shadows and spheres. With `image_path`, also writes that frame there as PNG, and the
// 16x reference beside it (NAME.reference.png).
struct ColourError {
  double against_16x = 0, against_64x = 0;
};
ColourError colour_error(const BenchSettings& settings, const std::string& image_path = "");
Timing time_overlay(const BenchSettings& settings, int frames);
Timing time_encoding(const BenchSettings& settings, int frames, const std::string& path);
// Draws, paints the overlay and encodes `frames` frames through demos::FramePipeline.
Timing time_end_to_end(const BenchSettings& settings, int frames, const std::string& path);
// The same frames, each written as a PNG into `directory`, then `ffmpeg` encodes them to `path`.
// Throws std::runtime_error if the ffmpeg program is missing or fails.
Timing time_naive_peer(const BenchSettings& settings, int frames, const std::string& directory, const std::string& path);

}  // namespace impulse::bench
