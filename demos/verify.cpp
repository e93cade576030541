#include "demos/verify.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "demos/film/moments.h"
#include "demos/golden_manifest.h"
#include "demos/verify_report.h"
#include "render/image_compare.h"
#include "render/png_io.h"

#ifndef IMPULSE_COMMIT
#define IMPULSE_COMMIT "unknown"
#endif

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

struct Still {
  double time = 0;
  render::Frame frame;
  std::vector<BodyPose> poses;
};

// The stills at `moments` (and at each impact that slows the video), with the scene's checks.
std::vector<Still> render_stills(const std::vector<Pane>& panes, RenderOptions options, const std::vector<double>& moments,
                                 bool at_impacts, std::vector<std::vector<CheckResult>>& checks) {
  options.video_path.clear();
  options.png_directory.clear();
  options.png_frames.clear();
  options.png_spread = 0;
  options.poster_path.clear();
  options.moments = moments;
  options.moments_at_impacts = at_impacts;
  std::vector<Still> stills;
  options.on_still = [&stills](double time, const render::Frame& frame, const std::vector<BodyPose>& poses) {
    stills.push_back({time, frame, poses});
  };
  checks = render_panes(panes, options);
  return stills;
}

// The default moments: the start, the middle and the end (the impacts come from the film).
std::vector<double> default_moments(const Scene& scene) {
  return parse_moments("0," + std::to_string(scene.duration / 2) + "," + std::to_string(scene.duration));
}

std::string golden_file(const std::string& directory, double time, const std::string& suffix = "") {
  return (fs::path(directory) / (moment_name(time) + suffix + ".png")).string();
}

GoldenManifest manifest_of(const Scene& scene, const RenderOptions& options, const VerifyOptions& verify,
                           const std::vector<Still>& stills) {
  GoldenManifest manifest;
  manifest.program = std::string("impulse (commit ") + IMPULSE_COMMIT + ")";
  manifest.scene = verify.scene_path;
  manifest.width = scene.video.width;
  manifest.height = scene.video.height;
  manifest.fps = scene.video.fps;
  manifest.quality = quality_name(manifest.width, manifest.height, manifest.fps);
  manifest.antialias = options.renderer.antialiasing == render::Antialiasing::edges  ? "edges"
                      : options.renderer.antialiasing == render::Antialiasing::msaa ? "msaa"
                                                                                    : "none";
  manifest.samples = options.renderer.samples;
  manifest.spheres = options.renderer.spheres == render::SphereMethod::tessellated ? "tessellated" : "impostor";
  manifest.shadows = options.renderer.shadows == render::ShadowMethod::shadow_map ? "map"
                     : options.renderer.shadows == render::ShadowMethod::none     ? "none"
                                                                                  : "ground";
  manifest.settings = verify.settings;
  for (const Still& still : stills) {
    manifest.moments.push_back(still.time);
    for (size_t i = 0; i < still.poses.size(); ++i)
      manifest.poses.push_back({still.time, int(i), scene.bodies[i].name, still.poses[i].position, still.poses[i].orientation});
  }
  return manifest;
}

// The bodies that moved or turned more than allowed since the goldens were recorded, one line each.
std::vector<std::string> compare_poses(const Still& still, const GoldenManifest& manifest,
                                       const std::vector<physics::BodyDef>& bodies) {
  std::vector<std::string> differences;
  std::vector<const GoldenPose*> recorded;
  for (const GoldenPose& pose : manifest.poses)
    if (moment_key(pose.time) == moment_key(still.time)) recorded.push_back(&pose);
  if (recorded.size() != still.poses.size()) {
    differences.push_back("the scene has " + std::to_string(still.poses.size()) + " bodies, the goldens " +
                          std::to_string(recorded.size()));
    return differences;
  }
  for (const GoldenPose* pose : recorded) {
    const BodyPose& now = still.poses.at(size_t(pose->index));
    const double moved = (now.position - pose->position).norm();
    const double turned = 2 * std::acos(std::min(1.0, std::abs(now.orientation.dot(pose->orientation))));
    if (moved <= kPoseMetres && turned <= kPoseRadians) continue;
    const physics::Vec3 by = now.position - pose->position;
    char line[400];
    std::snprintf(line, sizeof line,
                  "body '%s' moved %.4f m (by [%.4f, %.4f, %.4f]) and turned %.4f rad since the goldens (allowed: %g m, %g rad)",
                  bodies.at(size_t(pose->index)).name.c_str(), moved, by.x(), by.y(), by.z(), turned, kPoseMetres,
                  kPoseRadians);
    differences.push_back(line);
  }
  return differences;
}

// Writes the actual still, the diff and the strip beside the golden; returns their names.
MomentReport keep_failure(const std::string& directory, const Still& still, const render::Frame* golden,
                          const render::ImageDifference& difference) {
  MomentReport report;
  report.actual = golden_file(directory, still.time, ".actual");
  render::write_png(report.actual, still.frame);
  if (golden != nullptr) {
    const render::Frame diff = render::difference_image(*golden, still.frame, difference);
    report.diff = golden_file(directory, still.time, ".diff");
    render::write_png(report.diff, diff);
    report.strip = golden_file(directory, still.time, ".strip");
    render::write_png(report.strip, render::side_by_side({golden, &still.frame, &diff}));
  }
  return report;
}

void remove_failure_files(const std::string& directory, double time) {
  std::error_code ignored;
  for (const char* suffix : {".actual", ".diff", ".strip"}) fs::remove(golden_file(directory, time, suffix), ignored);
}

// One still against its golden and the recorded poses.
MomentReport compare_still(const std::string& directory, const Still& still, const GoldenManifest& manifest,
                           const std::vector<physics::BodyDef>& bodies, const std::string& size_note) {
  const std::string golden_path = golden_file(directory, still.time);
  if (!fs::exists(golden_path))
    throw std::invalid_argument("no golden " + golden_path + " (the manifest lists it): record the goldens again with --update");
  const render::Frame golden = render::read_png(golden_path);
  const render::ImageDifference difference = render::compare_images(golden, still.frame);
  const std::vector<std::string> moved = compare_poses(still, manifest, bodies);
  remove_failure_files(directory, still.time);
  MomentReport report;
  if (difference.matches && moved.empty()) {
    report.lines.push_back("t = " + moment_name(still.time).substr(2) + " s matches " + golden_path + " (" + difference.summary + ")");
  } else {
    report = keep_failure(directory, still, &golden, difference);
    const std::string what = difference.same_size ? difference.summary : size_note;
    report.lines.push_back("t = " + moment_name(still.time).substr(2) + " s DIFFERS from " + golden_path + ": " +
                           (difference.matches ? "the picture matches, the poses do not" : what) + "; see " +
                           report.strip + " (golden | actual | diff)");
    for (const std::string& line : moved) report.lines.push_back("t = " + moment_name(still.time).substr(2) + " s: " + line);
  }
  report.passed = difference.matches && moved.empty();
  report.golden = golden_path;
  report.time = still.time;
  return report;
}

VerifyResult update_goldens(const std::vector<Pane>& panes, const RenderOptions& options, const VerifyOptions& verify) {
  const Scene& scene = *panes.front().scene;
  VerifyResult result;
  const bool defaults = verify.moments.empty();
  const std::vector<Still> stills = render_stills(panes, options, defaults ? default_moments(scene) : verify.moments,
                                                  defaults && scene.playback.slow_motion_impulse > 0, result.checks);
  fs::create_directories(verify.golden_directory);
  for (const Still& still : stills) {
    render::write_png(golden_file(verify.golden_directory, still.time), still.frame);
    remove_failure_files(verify.golden_directory, still.time);
    result.lines.push_back("wrote " + golden_file(verify.golden_directory, still.time));
  }
  write_manifest(verify.golden_directory, manifest_of(scene, options, verify, stills));
  result.lines.push_back("wrote " + manifest_path(verify.golden_directory) + " and " + poses_path(verify.golden_directory));
  return result;
}

}  // namespace

VerifyResult verify_scene(const std::vector<Pane>& panes, RenderOptions options, const VerifyOptions& verify) {
  if (verify.update) return update_goldens(panes, options, verify);
  const Scene& scene = *panes.front().scene;
  const GoldenManifest manifest = read_manifest(verify.golden_directory);
  const std::vector<double> moments = verify.moments.empty() ? manifest.moments : verify.moments;
  for (const double moment : moments)
    if (std::none_of(manifest.moments.begin(), manifest.moments.end(),
                     [&](double recorded) { return moment_key(recorded) == moment_key(moment); }))
      throw std::invalid_argument("no golden at t = " + moment_name(moment).substr(2) + " s in " + verify.golden_directory +
                                  " (it has " + std::to_string(manifest.moments.size()) +
                                  " moments; see its manifest.toml): record it with --update --at");
  for (const double moment : moments)
    if (moment > scene.duration + 1e-9)
      throw std::invalid_argument("the golden at t = " + moment_name(moment).substr(2) + " s is past the scene's end (" +
                                  moment_name(scene.duration).substr(2) + " s): record the goldens again with --update");

  VerifyResult result;
  const std::vector<Still> stills = render_stills(panes, options, moments, false, result.checks);
  GoldenManifest now = manifest;
  now.width = scene.video.width, now.height = scene.video.height, now.fps = scene.video.fps;
  now.quality = quality_name(now.width, now.height, now.fps);
  const bool same_size = now.width == manifest.width && now.height == manifest.height;
  const std::string size_note = "the goldens are " + describe_size(manifest) + ", this run " + describe_size(now) +
                                ": re-run with " + size_options(manifest) + ", or with --update to record new goldens";
  if (!same_size) result.lines.push_back(size_note);
  if (verify.settings != manifest.settings) {  // allowed (that is how a change is tried), but said
    auto listed = [](const std::vector<std::string>& settings) {
      std::string text;
      for (const std::string& setting : settings) text += " --set " + setting;
      return text.empty() ? std::string(" no --set") : text;
    };
    result.lines.push_back("note: the goldens were recorded with" + listed(manifest.settings) + ", this run has" +
                           listed(verify.settings));
  }
  const size_t notes_end = result.lines.size();  // the lines so far are about the whole run
  std::vector<MomentReport> reports;
  for (const Still& still : stills) {
    reports.push_back(compare_still(verify.golden_directory, still, manifest, scene.bodies, size_note));
    result.passed = result.passed && reports.back().passed;
    result.lines.insert(result.lines.end(), reports.back().lines.begin(), reports.back().lines.end());
  }
  result.passed = result.passed && same_size;
  result.report_path = (fs::path(verify.golden_directory) / "report.html").string();
  const std::vector<std::string> notes(result.lines.begin(), result.lines.begin() + notes_end);
  write_report(result.report_path, verify.scene_path, manifest, result.passed, notes, reports);
  result.lines.push_back((result.passed ? "passed: " : "FAILED: ") + std::to_string(reports.size()) +
                         " moments compared; report: " + result.report_path);
  return result;
}

}  // namespace impulse::demos
