// What a directory of golden stills was recorded with (DIR/manifest.toml) and every body's pose
// at each moment (DIR/poses.csv, metres and unit quaternions), so that `impulse verify` compares
// like with like, says what to re-run when the size differs, and checks the physics too.
#pragma once
#include <string>
#include <vector>

#include "physics/math.h"

namespace impulse::demos {

struct GoldenPose {
  double time = 0;  // simulated s
  int index = 0;    // the body's, from 0, as the scene builds them
  std::string body;
  physics::Vec3 position = physics::Vec3::Zero();
  physics::Quat orientation = physics::Quat::Identity();
};

struct GoldenManifest {
  std::string program;  // the impulse that recorded them
  std::string scene;    // the scene file
  int width = 0, height = 0, fps = 0;
  std::string quality;  // "low", "medium", "high", or "custom" (named by the size and rate)
  std::string antialias = "msaa";  // edges, msaa or none
  int samples = 4;                 // with msaa
  std::string spheres, shadows;
  std::vector<std::string> settings;  // the --set arguments
  std::vector<double> moments;        // s of simulated time, one golden still each (moments_ms in the file)
  std::vector<GoldenPose> poses;      // every body at every moment
};

std::string manifest_path(const std::string& directory);  // DIRECTORY/manifest.toml
std::string poses_path(const std::string& directory);     // DIRECTORY/poses.csv

// Throws render::OutputError when a file cannot be written.
void write_manifest(const std::string& directory, const GoldenManifest& manifest);
// Throws std::invalid_argument naming the file and what to run when it is missing or unreadable.
GoldenManifest read_manifest(const std::string& directory);

// "low" for 854x480 at 15 fps, ... "custom".
std::string quality_name(int width, int height, int fps);
// The options that render at the manifest's size and rate: "--quality low", or "--width 800 --height 600 --fps 24".
std::string size_options(const GoldenManifest& manifest);
// "854x480 at 15 fps (--quality low)" or "800x600 at 24 fps (--width 800 --height 600 --fps 24)".
std::string describe_size(const GoldenManifest& manifest);

}  // namespace impulse::demos
