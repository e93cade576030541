// render_bench: how fast a frame of 300 spheres, 100 boxes and 400 arrows (with a lecture
// overlay) goes from a draw list to an MP4, phase by phase, against the naive peer (a PNG file
// per frame, then the ffmpeg program). Prints one table; tests/bench/README.md records its figures.
// Beside each way of drawing, its anti-aliasing's mean colour error (0..255 a channel, over every
// pixel of the first frame, before the overlay) against a 16x supersampled reference: the frame
// drawn without anti-aliasing at 16 sub-pixel offsets, one jittered in each cell of a 4x4 grid,
// and averaged (render/antialias_reference.h says why jittered); and against a 64x one (8x8).
//
//   render_bench                   1280x720, 90 frames a phase, and peak memory of 10 s and 60 s videos
//   render_bench --frames 300      more frames per phase
//   render_bench --no-memory       skip the 10 s / 60 s memory runs (they take a few minutes)
//   render_bench --smoke           320x240, a few frames: checks that everything runs (for ctest)
//   render_bench --aa-images DIR   also writes the first frame of each way of drawing and its
//                                  reference as PNG into DIR (edges.png, edges.reference.png, ...)
//
// Machines are shared and noisy: only figures from one run compare; the table says what else was
// running (load average) and how many threads llvmpipe used.
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "demos/film/render_scene.h"
#include "demos/scene/scene_file.h"
#include "tests/bench/core_latency.h"
#include "tests/bench/render_phases.h"

extern char** environ;

namespace fs = std::filesystem;
using namespace impulse;

namespace {

struct Options {
  int frames = 90;
  bool smoke = false;
  bool memory = true;
  std::string aa_images;  // a directory, or empty
  int child_seconds = 0;  // internal: render a video this long and exit (a memory run)
  std::string work = (fs::temp_directory_path() / "impulse_render_bench").string();
};

std::string load_average() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  file >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

const char* env_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value ? value : fallback;
}

// `error` < 0: not measured.
void row(const char* what, const bench::Timing& timing, bench::ColourError error = {-1, -1}) {
  char error_16x[16] = "-", error_64x[16] = "-";
  if (error.against_16x >= 0) std::snprintf(error_16x, sizeof error_16x, "%.4f", error.against_16x);
  if (error.against_64x >= 0) std::snprintf(error_64x, sizeof error_64x, "%.4f", error.against_64x);
  std::printf("| %-44s | %8.1f | %8.1f | %8.1f | %9s | %9s |\n", what, timing.frames_per_second(),
              1000.0 * timing.wall_seconds / timing.frames, 1000.0 * timing.cpu_seconds / timing.frames, error_16x,
              error_64x);
  std::fflush(stdout);
}

// Peak resident memory (MiB) of this program rendering a `seconds` long video end to end, in a
// child process of its own so that each figure is its own peak.
double peak_memory_of_video(const char* self, int seconds, const std::string& work) {
  const std::string seconds_text = std::to_string(seconds);
  std::vector<char*> argv = {const_cast<char*>(self), const_cast<char*>("--child-video"),
                             const_cast<char*>(seconds_text.c_str()), const_cast<char*>("--work"),
                             const_cast<char*>(work.c_str()), nullptr};
  pid_t child = 0;
  if (posix_spawn(&child, self, nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return double(usage.ru_maxrss) / 1024.0;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// `impulse compare` against one pane: assets/scenes/bounce.toml end to end to MP4 at the bench's
// size, alone and as two panes (friction on and off) of the same size of video. Goal: <= 1.5x.
// Two panes simulate two worlds and draw two smaller images (each a quarter of the frame's pixels,
// with the same geometry and shadows) into one frame that is encoded once.
void time_comparison(const bench::BenchSettings& settings, bool smoke, const std::string& work) {
  demos::Scene alone = demos::load_scene(IMPULSE_SOURCE_DIR "/assets/scenes/bounce.toml");
  alone.video.width = settings.width;
  alone.video.height = settings.height;
  if (smoke) alone.duration = 0.3;
  demos::Scene off = alone;
  off.world.contact.friction = false;
  demos::RenderOptions options;
  options.video_path = (fs::path(work) / "compare.mp4").string();
  // Interleaved, the faster of two runs each: the first run of a process also starts llvmpipe.
  double one = 1e30, two = 1e30;
  for (int round = 0; round < (smoke ? 1 : 2); ++round) {
    const auto one_start = std::chrono::steady_clock::now();
    demos::render_scene(alone, options);
    one = std::min(one, seconds_since(one_start));
    const auto two_start = std::chrono::steady_clock::now();
    demos::render_panes({{&alone, "friction on"}, {&off, "friction off"}}, options);
    two = std::min(two, seconds_since(two_start));
  }
  std::printf("\ncomparison (bounce.toml, %.1f s, %dx%d): one pane %.2f s, two panes %.2f s = %.2fx (goal: <= 1.5x)\n",
              alone.duration, settings.width, settings.height, one, two, two / one);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const bool has_value = i + 1 < argc;
    if (argument == "--frames" && has_value) options.frames = std::max(1, std::atoi(argv[++i]));
    else if (argument == "--smoke") options.smoke = true;
    else if (argument == "--no-memory") options.memory = false;
    else if (argument == "--aa-images" && has_value) options.aa_images = argv[++i];
    else if (argument == "--child-video" && has_value) options.child_seconds = std::atoi(argv[++i]);
    else if (argument == "--work" && has_value) options.work = argv[++i];
    else {
      std::fprintf(stderr, "render_bench: unknown argument '%s' (see the top of tests/bench/render_bench.cpp)\n",
                   argument.c_str());
      std::exit(2);
    }
  }
  if (options.smoke) {
    options.frames = 6;
    options.memory = false;
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  bench::BenchSettings settings;
  if (options.smoke) {
    settings.width = 320;
    settings.height = 240;
  }
  fs::create_directories(options.work);
  const std::string video = (fs::path(options.work) / "bench.mp4").string();
  try {
    if (options.child_seconds > 0) {
      bench::time_end_to_end(settings, options.child_seconds * settings.fps, video);
      return 0;
    }
    const int frames = options.frames;
    std::printf("render_bench: %dx%d, %d frames per phase, 300 spheres + 100 boxes + 400 arrows + overlay\n",
                settings.width, settings.height, frames);
    std::printf("machine: %u cores; LP_NUM_THREADS=%s LP_NATIVE_VECTOR_WIDTH=%s; load average at start %s;\n"
                "  a cache line's round trip between the first two cores %.0f ns (about 60 together, 350 apart)\n",
                std::thread::hardware_concurrency(), env_or("LP_NUM_THREADS", "(all cores)"),
                env_or("LP_NATIVE_VECTOR_WIDTH", "(native)"), load_average().c_str(), bench::core_round_trip_ns());
    std::printf("\n| %-44s | %8s | %8s | %8s | %9s | %9s |\n", "phase", "frames/s", "ms/frame", "cpu ms", "error 16x",
                "error 64x");
    std::printf("|%s|%s|%s|%s|%s|%s|\n", std::string(46, '-').c_str(), std::string(10, '-').c_str(),
                std::string(10, '-').c_str(), std::string(10, '-').c_str(), std::string(11, '-').c_str(),
                std::string(11, '-').c_str());

    bench::BenchSettings msaa = settings, tessellated = settings, single = settings;
    msaa.renderer.antialiasing = render::Antialiasing::msaa;
    msaa.renderer.samples = 4;
    tessellated.renderer = msaa.renderer;
    tessellated.renderer.spheres = render::SphereMethod::tessellated;
    single.renderer.antialiasing = render::Antialiasing::none;
    auto image = [&](const char* name) {
      if (options.aa_images.empty()) return std::string();
      fs::create_directories(options.aa_images);
      return (fs::path(options.aa_images) / (std::string(name) + ".png")).string();
    };
    const bench::ColourError edges_error = bench::colour_error(settings, image("edges"));
    const bench::ColourError msaa_error = bench::colour_error(msaa, image("msaa4"));
    row("draw, edge AA, sphere impostors (default)", bench::time_drawing(settings, frames), edges_error);
    row("draw, 4x MSAA, sphere impostors", bench::time_drawing(msaa, frames), msaa_error);
    row("draw, 4x MSAA, tessellated spheres", bench::time_drawing(tessellated, frames),
        bench::colour_error(tessellated, image("msaa4_tessellated")));
    row("draw, no anti-aliasing", bench::time_drawing(single, frames), bench::colour_error(single, image("none")));
    row("overlay (cairo) onto the frame", bench::time_overlay(settings, frames));
    const std::string encode = "encode (RGBA -> yuv420p, libx264 " + settings.video().preset + ")";
    row(encode.c_str(), bench::time_encoding(settings, frames, video));
    const bench::Timing ours = bench::time_end_to_end(settings, frames, video);
    row("end to end to MP4 (impulse, edge AA)", ours);
    row("end to end to MP4, 4x MSAA", bench::time_end_to_end(msaa, frames, video));
    bench::Timing naive;
    bool have_naive = true;
    try {
      naive = bench::time_naive_peer(settings, frames, (fs::path(options.work) / "png").string(),
                                     (fs::path(options.work) / "naive.mp4").string());
      row("naive peer: PNG per frame + ffmpeg program", naive);
    } catch (const std::exception& error) {
      have_naive = false;
      std::printf("| %-44s | %8s | %8s | %8s |\n", "naive peer: skipped", "-", "-", "-");
      std::printf("  (%s)\n", error.what());
    }
    std::printf("\nanti-aliasing: edge AA's error %.4f against 4x MSAA's %.4f (16x reference; 64x: %.4f against %.4f); "
                "goal: no worse\n", edges_error.against_16x, msaa_error.against_16x, edges_error.against_64x,
                msaa_error.against_64x);
    std::printf("end to end with edge AA: %.1f frames/s at %dx%d (goal: >= 60)\n", ours.frames_per_second(),
                settings.width, settings.height);
    if (have_naive && naive.frames_per_second() > 0)
      std::printf("\nend to end: %.1f frames/s = %.2fx the naive peer (goal: >= 30 frames/s and >= 3x)\n",
                  ours.frames_per_second(), ours.frames_per_second() / naive.frames_per_second());
    time_comparison(settings, options.smoke, options.work);
    if (options.memory) {
      const double ten = peak_memory_of_video(argv[0], 10, options.work);
      const double sixty = peak_memory_of_video(argv[0], 60, options.work);
      std::printf("peak memory, end to end: 10 s video %.0f MiB, 60 s video %.0f MiB\n", ten, sixty);
    }
    std::printf("load average at end %s; cores' round trip %.0f ns\n", load_average().c_str(), bench::core_round_trip_ns());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "render_bench: %s\n", error.what());
    return 1;
  }
  fs::remove_all(options.work);
  return 0;
}
