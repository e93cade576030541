// Captions in whole scenes: where and when a [[caption]] appears in the frames, and how it fades.
#include "demos/film/captions.h"
#include "demos/film/render_scene.h"
#include "demos/scene/scene_file.h"
#include "render/png_io.h"

#include <gtest/gtest.h>

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

// Beside the video, a WebVTT track with the cues in video time: at real time, as simulated; in
// slow motion (a fifth of real time around an impact), stretched.
TEST(Overlay, TheCaptionsTrackHasTheCuesInVideoTime) {
  const fs::path dir = fs::temp_directory_path() / "impulse_captions_track_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene_text = R"(
[scene]
duration = 1.2
[video]
width = 160
height = 120
fps = 10
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
  std::ofstream(dir / "real_time.toml") << scene_text;
  demos::RenderOptions options;
  options.video_path = (dir / "real_time.mp4").string();
  demos::render_scene(demos::load_scene((dir / "real_time.toml").string()), options);
  std::ifstream real_time(dir / "real_time.vtt");
  const std::string track((std::istreambuf_iterator<char>(real_time)), std::istreambuf_iterator<char>());
  EXPECT_EQ(track, "WEBVTT\n\n1\n00:00:00.400 --> 00:00:00.800\nMomentum is kept\n");
  // Without impacts that slow the video, a chapter at each caption: the first starts the video.
  std::ifstream chapters(dir / "real_time.chapters.vtt");
  const std::string chapter_track((std::istreambuf_iterator<char>(chapters)), std::istreambuf_iterator<char>());
  EXPECT_EQ(chapter_track,
            "WEBVTT\n\n1\n00:00:00.000 --> 00:00:00.400\nStart\n\n2\n00:00:00.400 --> 00:00:01.200\nMomentum is kept\n");

  // One caption from the start is a chapter too: it names the video's one chapter.
  std::string from_start = scene_text;
  from_start.replace(from_start.find("start = 0.4"), 11, "start = 0.0");
  std::ofstream(dir / "from_start.toml") << from_start;
  options.video_path = (dir / "from_start.mp4").string();
  demos::render_scene(demos::load_scene((dir / "from_start.toml").string()), options);
  std::ifstream one(dir / "from_start.chapters.vtt");
  const std::string one_chapter((std::istreambuf_iterator<char>(one)), std::istreambuf_iterator<char>());
  EXPECT_EQ(one_chapter, "WEBVTT\n\n1\n00:00:00.000 --> 00:00:01.200\nMomentum is kept\n");

  std::ofstream(dir / "slow.toml") << scene_text << "[playback]\nspeed = 0.2\n";
  options.video_path = (dir / "slow.mp4").string();
  demos::render_scene(demos::load_scene((dir / "slow.toml").string()), options);
  std::ifstream slow(dir / "slow.vtt");
  const std::string slow_track((std::istreambuf_iterator<char>(slow)), std::istreambuf_iterator<char>());
  EXPECT_NE(slow_track.find("00:00:02.000 --> 00:00:04.000"), std::string::npos) << slow_track;
  fs::remove_all(dir);
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
}  // namespace
}  // namespace impulse
