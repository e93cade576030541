// Frames -> a video file through libavformat/libavcodec/libswscale (and libavfilter for GIF's
// palettes): H.264 MP4 (yuv420p, BT.709 tags, faststart), VP9 WebM (with an alpha channel where
// asked: yuva420p) or an animated GIF (a palette made for each frame, dithered; loops for ever).
// The file appears under its name only after finish(); until then it is `path + ".part"`, and an
// encoder destroyed before finish() (e.g. by an exception) deletes it.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "render/frame.h"

namespace impulse::render {

enum class VideoFormat { mp4, webm, gif };

const char* format_name(VideoFormat format);  // "mp4", "webm", "gif": also the file's extension
// The format a file name's extension names (.mp4, .webm, .gif, any case), if any.
std::optional<VideoFormat> format_of_path(std::string_view path);

struct VideoSettings {
  VideoFormat format = VideoFormat::mp4;
  bool alpha = false;  // WebM only: the frames' alpha kept (a transparent background over a slide)
  int width = 1280;   // both must be even (4:2:0 chroma)
  int height = 720;
  int fps = 30;
  int crf = 20;       // x264 constant rate factor: 0 lossless .. 51 worst; ~18-23 looks clean (VP9: scaled to 0..63)
  std::string preset = "ultrafast";  // x264's speed preset: ultrafast, superfast, veryfast, faster, ... medium (MP4 only)
  int threads = 0;                  // x264's threads; 0: its own choice (1.5 per core)
  std::string comment = "";         // the file's comment tag (e.g. how it was made); empty: none
};

class VideoEncoder {
 public:
  // Opens `path + ".part"` and writes the header. Throws std::invalid_argument for bad settings,
  // std::runtime_error (with the path and FFmpeg's reason) for everything else. The first encoder
  // lowers FFmpeg's global log level from its default (info) to warning.
  VideoEncoder(std::string path, VideoSettings settings = {});
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Frame i is shown at time i / fps. Throws std::invalid_argument if its size differs from the
  // settings, std::logic_error after finish() or after an earlier error, std::runtime_error on
  // FFmpeg errors.
  void add_frame(const Frame& frame);

  // Flushes the encoder, writes the trailer and renames the .part file to `path`. A second call
  // does nothing. Throws std::logic_error if no frame was added (the .part file is then deleted
  // with the encoder).
  void finish();

  const std::string& path() const;
  int64_t frame_count() const;
  bool finished() const;

 private:
  struct State;  // FFmpeg objects, kept out of this header
  std::unique_ptr<State> state_;
};

}  // namespace impulse::render
