// The 2D overlay: a caption's pixels appear where the caption is placed and only during its time
// cue; the rest of the frame is untouched by the layer; the label sits beside its arrow's tip.
#include "demos/captions.h"
#include "demos/render_scene.h"
#include "demos/scene_file.h"
#include "render/overlay_painter.h"
#include "render/png_io.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace impulse {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 320;
constexpr int kHeight = 240;

int luminance(const render::Frame& frame, int x, int y) {
  const uint8_t* p = &frame.rgba[(size_t(y) * frame.width + x) * 4];
  return (2126 * p[0] + 7152 * p[1] + 722 * p[2]) / 10000;
}

// Dark pixels (the caption's box) in the bottom band where captions sit, and bright ones (its
// letters) between a row's first and last dark pixel.
struct CaptionPixels {
  int dark = 0;
  int bright = 0;
};
CaptionPixels caption_band(const render::Frame& frame) {
  CaptionPixels pixels;
  for (int y = kHeight * 3 / 4; y < kHeight; ++y) {
    int first = -1, last = -1;
    for (int x = kWidth / 5; x < kWidth * 4 / 5; ++x) {
      if (luminance(frame, x, y) < 70) {
        ++pixels.dark;
        if (first < 0) first = x;
        last = x;
      }
    }
    for (int x = first + 1; first >= 0 && x < last; ++x)
      if (luminance(frame, x, y) > 150) ++pixels.bright;
  }
  return pixels;
}

// Frames at 10 per second; the caption is on from 0.4 s to 0.8 s of simulated time.
TEST(Overlay, CaptionAppearsWhereItIsPlacedOnlyDuringItsCue) {
  const fs::path dir = fs::temp_directory_path() / "impulse_overlay_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "caption.toml") << R"(
[scene]
duration = 1.2
[camera]
position = [0, 1.5, 5]
target = [0, 0.5, 0]
[video]
width = 320
height = 240
fps = 10
[overlay]
clock = false
legend = false
[[caption]]
text = "Momentum is kept"
start = 0.4
end = 0.8
[[body]]
shape = "plane"
[[body]]
shape = "sphere"
radius = 0.3
position = [0, 0.3, -2]
)";
  const demos::Scene scene = demos::load_scene((dir / "caption.toml").string());
  demos::RenderOptions options;
  options.png_directory = (dir / "frames").string();
  demos::render_scene(scene, options);

  for (int frame = 0; frame < 12; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    const render::Frame image = render::read_png((dir / "frames" / name).string());
    const CaptionPixels pixels = caption_band(image);
    const double time = frame / 10.0;
    if (time >= 0.5 && time <= 0.7) {  // fully faded in
      EXPECT_GT(pixels.dark, 800) << "t = " << time << ": the caption's box";
      EXPECT_GT(pixels.bright, 20) << "t = " << time << ": the caption's letters";
    } else if (time < 0.4 || time >= 0.8) {
      EXPECT_EQ(pixels.dark, 0) << "t = " << time << ": no caption outside its cue";
      EXPECT_EQ(pixels.bright, 0) << "t = " << time;
    }
  }
}

TEST(Overlay, CaptionsFadeInsideTheirCue) {
  const std::vector<demos::CaptionCue> cues = {{"a", 1.0, 2.0}, {"b", 1.5, 3.0}};
  EXPECT_TRUE(demos::captions_at(cues, 0.99).empty());
  ASSERT_EQ(demos::captions_at(cues, 1.0).size(), 1u);
  EXPECT_GT(demos::captions_at(cues, 1.0)[0].opacity, 0.0f);
  EXPECT_FLOAT_EQ(demos::captions_at(cues, 1.3)[0].opacity, 1.0f);
  EXPECT_EQ(demos::captions_at(cues, 1.7).size(), 2u);
  ASSERT_EQ(demos::captions_at(cues, 2.0).size(), 1u);
  EXPECT_EQ(demos::captions_at(cues, 2.0)[0].text, "b");
}

// The layer changes only the pixels it paints: everything outside its panels stays byte-exact,
// and cairo's premultiplied BGRA lands as the right colour in the RGBA frame.
TEST(Overlay, CompositesOnlyWhereItPaintsInTheRightColour) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 0)};
  for (size_t i = 0; i < frame.rgba.size(); i += 4) {
    frame.rgba[i] = 40;
    frame.rgba[i + 1] = 200;
    frame.rgba[i + 2] = 90;
    frame.rgba[i + 3] = 255;
  }
  const render::Frame before = frame;
  render::Overlay overlay;
  overlay.captions = {{"Caption", 1.0f}};
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(overlay, frame);
  // The top half has nothing painted.
  for (int y = 0; y < kHeight / 2; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(frame.rgba[(size_t(y) * kWidth + x) * 4 + c], before.rgba[(size_t(y) * kWidth + x) * 4 + c]);
  // The caption box is dark grey over green: dark, still a little green, never red or blue.
  bool found_box = false;
  for (int y = kHeight * 3 / 4; y < kHeight && !found_box; ++y) {
    const uint8_t* p = &frame.rgba[(size_t(y) * kWidth + kWidth / 2) * 4];
    if (p[1] < 80) {
      found_box = true;
      EXPECT_GT(p[1], p[0]) << "green shows through the box";
      EXPECT_GT(p[1], p[2]);
      EXPECT_EQ(p[3], 255);
    }
  }
  EXPECT_TRUE(found_box);
  // A second paint with nothing clears what the first painted.
  render::Frame again = before;
  painter.paint(render::Overlay{}, again);
  EXPECT_TRUE(again.rgba == before.rgba);
}

TEST(Overlay, LabelSitsBesideItsAnchor) {
  render::Frame frame{kWidth, kHeight, std::vector<uint8_t>(size_t(kWidth) * kHeight * 4, 255)};
  render::Overlay overlay;
  overlay.labels = {{render::Vec2f(100, 120), "J = 2.41 N\u00b7s", {0.0f, 0.45f, 0.7f}}};
  render::OverlayPainter painter(kWidth, kHeight);
  painter.paint(overlay, frame);
  int inked_right = 0, inked_left = 0;
  for (int y = 100; y < 125; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const uint8_t* p = &frame.rgba[(size_t(y) * kWidth + x) * 4];
      if (p[2] > p[0] + 60) (x > 100 ? inked_right : inked_left)++;
    }
  }
  EXPECT_GT(inked_right, 30) << "blue letters to the right of the anchor";
  EXPECT_EQ(inked_left, 0);
}

}  // namespace
}  // namespace impulse
