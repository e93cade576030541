// Every video format written and decoded back (libavcodec): MP4, WebM with and without alpha,
// GIF; frame for frame, in size and colour.
#include "render/video_encoder.h"
#include "tests/support/video_decode.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace impulse {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 96, kHeight = 64, kFrames = 20, kFps = 10;

// A path in the system's temporary directory, nothing there yet (each test its own names).
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "impulse_video_formats";
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

// Frame i: the left half a grey that brightens with i, the right half a fixed orange; with
// `alpha`, a transparent background and an opaque orange square in the middle instead.
render::Frame pattern(int i, bool alpha) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4)};
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      uint8_t* p = &frame.rgba[(size_t(y) * kWidth + x) * 4];
      const bool square = x >= 32 && x < 64 && y >= 16 && y < 48;
      const bool orange = alpha ? square : x >= kWidth / 2;
      const uint8_t grey = uint8_t(40 + 10 * i);
      p[0] = orange ? 230 : grey;
      p[1] = orange ? 159 : grey;
      p[2] = orange ? 0 : grey;
      p[3] = alpha && !square ? 0 : 255;
    }
  }
  return frame;
}

const uint8_t* at(const render::Frame& frame, int x, int y) { return &frame.rgba[(size_t(y) * frame.width + x) * 4]; }

testing::DecodedVideo write_and_decode(render::VideoFormat format, bool alpha) {
  render::VideoSettings settings;
  settings.format = format;
  settings.alpha = alpha;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.fps = kFps;
  const std::string path = scratch(std::string(alpha ? "alpha." : "video.") + render::format_name(format)).string();
  render::VideoEncoder encoder(path, settings);
  for (int i = 0; i < kFrames; ++i) encoder.add_frame(pattern(i, alpha));
  encoder.finish();
  return testing::decode_video(path);
}

TEST(VideoFormats, EachIsWrittenAndDecodedBackFrameForFrame) {
  for (const render::VideoFormat format : {render::VideoFormat::mp4, render::VideoFormat::webm, render::VideoFormat::gif}) {
    SCOPED_TRACE(render::format_name(format));
    const testing::DecodedVideo video = write_and_decode(format, false);
    EXPECT_EQ(video.width, kWidth);
    EXPECT_EQ(video.height, kHeight);
    ASSERT_EQ(video.frames.size(), size_t(kFrames));
    if (format != render::VideoFormat::gif) {
      EXPECT_NEAR(video.fps, kFps, 0.01);
    }
    // GIF's palettes hold a frame's few colours exactly; the others are within their chroma's loss.
    const int tolerance = format == render::VideoFormat::gif ? 0 : 6;
    for (int i = 0; i < kFrames; ++i) {
      const uint8_t* grey = at(video.frames[size_t(i)], 20, 30);
      const uint8_t* orange = at(video.frames[size_t(i)], 76, 30);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(grey[c], 40 + 10 * i, tolerance) << "frame " << i << " channel " << c;
      EXPECT_NEAR(orange[0], 230, tolerance) << "frame " << i;
      EXPECT_NEAR(orange[1], 159, tolerance) << "frame " << i;
      EXPECT_NEAR(orange[2], 0, tolerance) << "frame " << i;
    }
  }
}

TEST(VideoFormats, AWebmKeepsItsAlpha) {
  const testing::DecodedVideo video = write_and_decode(render::VideoFormat::webm, true);
  ASSERT_EQ(video.frames.size(), size_t(kFrames));
  for (const render::Frame& frame : video.frames) {
    EXPECT_LE(at(frame, 8, 8)[3], 4) << "the background is transparent";
    const uint8_t* square = at(frame, 48, 32);
    EXPECT_GE(square[3], 251) << "the body is opaque";
    EXPECT_NEAR(square[0], 230, 6);
    EXPECT_NEAR(square[1], 159, 6);
  }
}

TEST(VideoFormats, AlphaIsRefusedWhereTheFormatCannotKeepIt) {
  for (const render::VideoFormat format : {render::VideoFormat::mp4, render::VideoFormat::gif}) {
    render::VideoSettings settings;
    settings.format = format;
    settings.alpha = true;
    try {
      render::VideoEncoder encoder(scratch("refused").string(), settings);
      ADD_FAILURE() << "no error for " << render::format_name(format);
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("needs WebM"), std::string::npos) << error.what();
    }
  }
  EXPECT_FALSE(fs::exists(scratch("refused"))) << "nothing left behind";
}

TEST(VideoFormats, AFilesExtensionNamesItsFormat) {
  EXPECT_EQ(render::format_of_path("out/a.mp4"), render::VideoFormat::mp4);
  EXPECT_EQ(render::format_of_path("slides/A.WebM"), render::VideoFormat::webm);
  EXPECT_EQ(render::format_of_path("loop.gif"), render::VideoFormat::gif);
  EXPECT_EQ(render::format_of_path("clip.mov"), std::nullopt);
  EXPECT_EQ(render::format_of_path("out.gif/frames"), std::nullopt);
  EXPECT_EQ(render::format_of_path("frames"), std::nullopt);
}

}  // namespace
}  // namespace impulse
