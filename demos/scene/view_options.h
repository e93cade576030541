// What a scene file asks the video to show beyond the bodies (docs/scene_files.md):
// captions with time cues, the 2D overlay, camera motion, playback speed and slow motion.
#pragma once
#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace impulse::demos {

using Vec3f = Eigen::Vector3f;

struct Colour { float r = 0.8f, g = 0.8f, b = 0.8f; };  // sRGB, 0..1

// [camera]: where the eye is, what it looks at, and its vertical field of view.
struct CameraSetting {
  Vec3f position{0.0f, 3.0f, 10.0f};
  Vec3f target{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
};

// [video]: the frame's size and rate, and how the encoder trades quality for size and speed.
struct VideoSetting {
  int width = 1280;   // even
  int height = 720;   // even
  int fps = 30;
  int crf = 20;       // x264 constant rate factor: 0 lossless .. 51 worst
  std::string preset = "ultrafast";  // x264's speed preset: half superfast's encoding time, files 1.3-1.9x as large
};

// [[caption]]: a line shown from `start` to `end` seconds of simulated time. In a comparison
// ([compare]) it may belong to one pane (`pane = N`, from 1) or name each pane's value or label
// (`{value}`, `{label}` in its text): then each pane shows its own, inside the pane.
struct CaptionCue {
  std::string text;
  double start = 0;
  double end = 1e9;
  int pane = 0;      // the pane it belongs to, from 1; 0: every pane
  bool own = false;  // a pane's own (scene_compare.h made it so): drawn inside the pane, not under them
};

// Whether a caption's text names the pane's value or label.
bool names_the_pane(const std::string& text);

enum class PlotKind { kinetic_energy, momentum, speed };

// [overlay]
struct OverlayOptions {
  bool title = true;             // the scene's title, top left
  bool clock = true;             // simulated time and playback speed, top right
  bool legend = true;            // what each arrow colour means, and its scale
  std::vector<PlotKind> plots;   // live plots down the right side
  std::vector<std::string> plot_bodies;  // whose speeds the "speed" plot shows (default: the first moving
                                         // body); several: a curve each, in the body's colour
  double plot_from = 0;          // s: the plots' time axis starts here (to leave out a landing's spike)
  std::string label = "impulse"; // the arrow that gets its value written beside it: impulse, velocity, none
  std::string label_body;        // on which body (default: whichever has the largest)
  std::string equation = "none"; // "eq8" or "eq13": filled in with the latest impact's numbers (needs slow motion)
};

// [[camera.keyframe]]: where the camera is at `time` s; it eases between keyframes.
struct CameraKeyframe {
  double time = 0;
  CameraSetting camera;
};

// [camera] follow / keyframes
struct CameraMotion {
  std::string follow;                   // a body's name: the camera keeps its offset from it
  std::vector<CameraKeyframe> keyframes;  // sorted by time; the [camera] fields are the one at t = 0
  bool fit = false;  // the camera aimed at, and moved along its line of sight until it sees, every moving body's whole path
};

// [playback]
struct PlaybackOptions {
  double speed = 1.0;                // video seconds per simulated second is 1 / speed
  double slow_motion_impulse = 0.0;  // N s: a contact impulse above this slows playback; 0: never
  double slow_motion_speed = 0.2;    // the playback factor around such an impact
  double slow_motion_window = 0.25;  // s of simulated time before and after the impact
  std::optional<double> poster;      // s of simulated time the poster shows; none: the teaching moment
};

}  // namespace impulse::demos
