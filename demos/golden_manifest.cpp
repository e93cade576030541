#include "demos/golden_manifest.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

#include "demos/film/moments.h"
#include "demos/scene/video_quality.h"
#include "render/part_file.h"

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

template <typename Write>
void write_file(const std::string& path, Write write) {
  render::PartFile part(path);
  {
    std::ofstream file(part.part_path());
    write(file);
    file.close();
    if (!file) throw render::OutputError("cannot write " + part.part_path());
  }
  part.commit();
}

std::vector<GoldenPose> read_poses(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::invalid_argument("no " + path + ": run verify with --update to record the goldens again");
  std::vector<GoldenPose> poses;
  std::string line;
  std::getline(file, line);  // the header
  for (int row = 2; std::getline(file, line); ++row) {
    std::stringstream cells(line);
    std::string cell;
    std::vector<std::string> fields;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    if (fields.size() != 10) throw std::invalid_argument(path + ":" + std::to_string(row) + ": expected 10 fields; run verify with --update");
    GoldenPose pose;
    try {
      pose.time = std::stod(fields[0]);
      pose.index = std::stoi(fields[1]);
      pose.body = fields[2];
      pose.position = {std::stod(fields[3]), std::stod(fields[4]), std::stod(fields[5])};
      pose.orientation = physics::Quat(std::stod(fields[6]), std::stod(fields[7]), std::stod(fields[8]), std::stod(fields[9]));
    } catch (const std::exception&) {
      throw std::invalid_argument(path + ":" + std::to_string(row) + ": not a number; run verify with --update");
    }
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace

std::string manifest_path(const std::string& directory) { return (fs::path(directory) / "manifest.toml").string(); }
std::string poses_path(const std::string& directory) { return (fs::path(directory) / "poses.csv").string(); }

void write_manifest(const std::string& directory, const GoldenManifest& manifest) {
  toml::array settings, moments;
  for (const std::string& setting : manifest.settings) settings.push_back(setting);
  for (const double moment : manifest.moments) moments.push_back(moment_key(moment));
  const toml::table table{{"program", manifest.program}, {"scene", manifest.scene},     {"width", manifest.width},
                          {"height", manifest.height},   {"fps", manifest.fps},         {"quality", manifest.quality},
                          {"antialias", manifest.antialias}, {"samples", manifest.samples},
                          {"spheres", manifest.spheres}, {"shadows", manifest.shadows},
                          {"settings", settings},        {"moments_ms", moments}};
  write_file(manifest_path(directory), [&](std::ofstream& file) {
    file << "# Written by `impulse verify --update`: what the golden stills t_*.png were rendered with.\n"
            "# poses.csv holds every body's pose at each moment.\n"
         << table << "\n";
  });
  write_file(poses_path(directory), [&](std::ofstream& file) {
    file << "time_s,index,body,x_m,y_m,z_m,qw,qx,qy,qz\n";
    char row[400];
    for (const GoldenPose& pose : manifest.poses) {
      std::string body = pose.body;  // the index names the body; a comma would split the row
      std::replace(body.begin(), body.end(), ',', ' ');
      std::snprintf(row, sizeof row, "%.3f,%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", pose.time, pose.index,
                    body.c_str(), pose.position.x(), pose.position.y(), pose.position.z(), pose.orientation.w(),
                    pose.orientation.x(), pose.orientation.y(), pose.orientation.z());
      file << row;
    }
  });
}

GoldenManifest read_manifest(const std::string& directory) {
  const std::string path = manifest_path(directory);
  if (!fs::exists(path))
    throw std::invalid_argument("no " + path + ": record the goldens first, with the same command and --update");
  toml::table table;
  try {
    table = toml::parse_file(path);
  } catch (const toml::parse_error& error) {
    throw std::invalid_argument(path + ": " + std::string(error.description()) + "; record the goldens again with --update");
  }
  GoldenManifest manifest;
  manifest.program = table["program"].value_or(std::string());
  manifest.scene = table["scene"].value_or(std::string());
  manifest.width = table["width"].value_or(0);
  manifest.height = table["height"].value_or(0);
  manifest.fps = table["fps"].value_or(0);
  manifest.quality = table["quality"].value_or(std::string());
  manifest.samples = table["samples"].value_or(4);
  // Goldens from before the choice of anti-aliasing were multisampled, or had none with 0 samples.
  manifest.antialias = table["antialias"].value_or(std::string(manifest.samples > 0 ? "msaa" : "none"));
  manifest.spheres = table["spheres"].value_or(std::string());
  manifest.shadows = table["shadows"].value_or(std::string());
  if (const toml::array* settings = table["settings"].as_array())
    for (const toml::node& setting : *settings) manifest.settings.push_back(setting.value_or(std::string()));
  if (const toml::array* moments = table["moments_ms"].as_array())
    for (const toml::node& moment : *moments) manifest.moments.push_back(double(moment.value_or(int64_t(-1))) / 1000);
  if (manifest.width <= 0 || manifest.height <= 0 || manifest.moments.empty())
    throw std::invalid_argument(path + ": no size or no moments; record the goldens again with --update");
  manifest.poses = read_poses(poses_path(directory));
  return manifest;
}

std::string quality_name(int width, int height, int fps) {
  for (const char* name : {"low", "medium", "high"}) {
    const VideoSetting preset = *quality_preset(name);
    if (preset.width == width && preset.height == height && preset.fps == fps) return name;
  }
  return "custom";
}

std::string size_options(const GoldenManifest& manifest) {
  if (manifest.quality != "custom") return "--quality " + manifest.quality;
  return "--width " + std::to_string(manifest.width) + " --height " + std::to_string(manifest.height) + " --fps " +
         std::to_string(manifest.fps);
}

std::string describe_size(const GoldenManifest& manifest) {
  return std::to_string(manifest.width) + "x" + std::to_string(manifest.height) + " at " + std::to_string(manifest.fps) +
         " fps (" + size_options(manifest) + ")";
}

}  // namespace impulse::demos
