#include "tests/bench/render_phases.h"

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "demos/film/frame_pipeline.h"
#include "render/antialias_reference.h"
#include "render/overlay_painter.h"
#include "render/png_io.h"
#include "tests/bench/bench_frame.h"

extern char** environ;

namespace impulse::bench {
namespace {

double process_cpu_seconds() {
  rusage self{}, children{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(self.ru_utime) + seconds(self.ru_stime) + seconds(children.ru_utime) + seconds(children.ru_stime);
}

class Stopwatch {
 public:
  Timing stop(int frames) const {
    return {frames, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count(),
            process_cpu_seconds() - cpu_};
  }

 private:
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  double cpu_ = process_cpu_seconds();
};

double frame_time(int frame, int fps) { return double(frame) / fps; }

// Runs a program and waits for it; throws if it cannot start or fails.
void run_program(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t child = 0;
  if (posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot start '" + arguments[0] + "' (install it: apt-get install " + arguments[0] + ")");
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw std::runtime_error("'" + arguments[0] + "' failed");
}

}  // namespace

render::VideoSettings BenchSettings::video() const {
  render::VideoSettings video;
  video.width = width;
  video.height = height;
  video.fps = fps;
  return video;
}

Timing time_drawing(const BenchSettings& settings, int frames) {
  render::Renderer renderer(settings.width, settings.height, settings.renderer);
  render::Frame frame;
  renderer.draw_into(bench_draw_list(0), frame);  // compiles the shaders' variants
  const Stopwatch watch;
  for (int i = 0; i < frames; ++i) renderer.draw_into(bench_draw_list(frame_time(i, settings.fps)), frame);
  return watch.stop(frames);
}

ColourError colour_error(const BenchSettings& settings, const std::string& image_path) {
  const render::DrawList scene = bench_draw_list(0);
  const render::Frame reference = render::supersampled_reference(settings.width, settings.height, settings.renderer, scene);
  const render::Frame fine = render::supersampled_reference(settings.width, settings.height, settings.renderer, scene, 8);
  render::Renderer renderer(settings.width, settings.height, settings.renderer);
  const render::Frame& frame = renderer.draw(scene);
  if (!image_path.empty()) {
    render::write_png(image_path, frame);
    render::write_png(std::filesystem::path(image_path).replace_extension(".reference.png").string(), reference);
  }
  return {render::mean_colour_error(frame, reference), render::mean_colour_error(frame, fine)};
}

Timing time_overlay(const BenchSettings& settings, int frames) {
  render::Renderer renderer(settings.width, settings.height, settings.renderer);
  const render::Frame drawn = renderer.draw(bench_draw_list(0));
  render::OverlayPainter painter(settings.width, settings.height);
  render::Frame frame = drawn;
  const double duration = double(frames) / settings.fps;
  const Stopwatch watch;
  for (int i = 0; i < frames; ++i) {
    frame.rgba = drawn.rgba;  // same size: no allocation
    painter.paint(bench_overlay(frame_time(i, settings.fps), duration), frame);
  }
  return watch.stop(frames);
}

Timing time_encoding(const BenchSettings& settings, int frames, const std::string& path) {
  // A few different drawn frames, cycled, so the encoder never sees a still picture.
  render::Renderer renderer(settings.width, settings.height, settings.renderer);
  std::vector<render::Frame> drawn;
  for (int i = 0; i < 8; ++i) drawn.push_back(renderer.draw(bench_draw_list(frame_time(i, settings.fps))));
  const Stopwatch watch;
  render::VideoEncoder encoder(path, settings.video());
  for (int i = 0; i < frames; ++i) encoder.add_frame(drawn[size_t(i) % drawn.size()]);
  encoder.finish();
  return watch.stop(frames);
}

Timing time_end_to_end(const BenchSettings& settings, int frames, const std::string& path) {
  const double duration = double(frames) / settings.fps;
  const Stopwatch watch;
  render::Renderer renderer(settings.width, settings.height, settings.renderer);
  render::VideoEncoder encoder(path, settings.video());
  render::OverlayPainter painter(settings.width, settings.height);
  demos::FramePipeline pipeline(3, [&](demos::FrameJob& job) {
    render::finish(job.drawn, job.frame);  // as impulse render does: the next frame draws meanwhile
    painter.paint(job.overlay, job.frame);
    encoder.add_frame(job.frame);
  });
  for (int i = 0; i < frames; ++i) {
    demos::FrameJob& job = pipeline.acquire();
    renderer.draw_into(bench_draw_list(frame_time(i, settings.fps)), job.drawn);
    job.overlay = bench_overlay(frame_time(i, settings.fps), duration);
    pipeline.submit();
  }
  pipeline.finish();
  encoder.finish();
  return watch.stop(frames);
}

Timing time_naive_peer(const BenchSettings& settings, int frames, const std::string& directory, const std::string& path) {
  const double duration = double(frames) / settings.fps;
  std::filesystem::create_directories(directory);
  const Stopwatch watch;
  render::Renderer renderer(settings.width, settings.height, settings.renderer);
  render::OverlayPainter painter(settings.width, settings.height);
  render::Frame frame;
  for (int i = 0; i < frames; ++i) {
    renderer.draw_into(bench_draw_list(frame_time(i, settings.fps)), frame);
    painter.paint(bench_overlay(frame_time(i, settings.fps), duration), frame);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    render::write_png((std::filesystem::path(directory) / name).string(), frame);
  }
  const render::VideoSettings video = settings.video();
  run_program({"ffmpeg", "-loglevel", "error", "-y", "-framerate", std::to_string(settings.fps), "-i",
               (std::filesystem::path(directory) / "frame_%05d.png").string(), "-c:v", "libx264", "-preset",
               video.preset, "-crf", std::to_string(video.crf), "-vf", "scale=out_color_matrix=bt709:out_range=tv",
               "-pix_fmt", "yuv420p", "-colorspace", "bt709",
               "-color_primaries", "bt709", "-color_trc", "bt709", "-movflags", "+faststart", path});
  return watch.stop(frames);
}

}  // namespace impulse::bench
