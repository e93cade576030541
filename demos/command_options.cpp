#include "demos/command_options.h"

#include "demos/film/moments.h"
#include "render/part_file.h"
#include "render/video_encoder.h"

#include <exception>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fs = std::filesystem;

namespace impulse::demos {
namespace {

std::vector<int> parse_frames(const std::string& list) {
  std::vector<int> frames;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    try {
      size_t used = 0;
      const int frame = std::stoi(item, &used);
      if (used != item.size() || frame < 0) throw std::invalid_argument(item);
      frames.push_back(frame);
    } catch (const std::exception&) {
      throw std::invalid_argument("--frames wants frame numbers from 0, separated by commas (like 0,45,90), got '" + list + "'");
    }
  }
  return frames;
}

}  // namespace

const char* const kExitCodesHelp =
    "\nExit codes: 0 done; 1 the scene file or the command line is wrong (nothing written); 2 a [[check]]\n"
    "of the scene or a golden frame (verify) failed (outputs written); 3 the output cannot be written (nothing replaced, no temporary\n"
    "left); 4 anything else failed; 130 / 143 interrupted by SIGINT / SIGTERM.";

std::string examples_footer(const std::string& examples) { return "\nExamples:\n" + examples + kExitCodesHelp; }

void add_scene_options(CLI::App* command, SceneArguments& arguments) {
  command->add_option("--set", arguments.settings,
                      "KEY=VALUE: a scene field over the file's, checked as the file's are; repeatable. "
                      "world.friction=false, world.method=projection, body[ball].restitution=0.2, body[0].mass=2, "
                      "video.quality=low, caption[1].text=Hello (a bare word is a string)")
      ->type_name("KEY=VALUE");
}

void add_video_options(CLI::App* command, VideoOverrides& overrides) {
  add_scene_options(command, overrides.scene_arguments);
  command->add_option("--quality", overrides.quality,
                      "Preset: low (854x480, 15 fps), medium (1280x720, 30 fps), high (1920x1080, 60 fps); "
                      "default: the scene's [video], else medium")
      ->check(CLI::IsMember({"low", "medium", "high"}));
  command->add_option("--width", overrides.width, "Frame width in pixels (even), over the preset")->check(CLI::Range(16, 7680));
  command->add_option("--height", overrides.height, "Frame height in pixels (even)")->check(CLI::Range(16, 4320));
  command->add_option("--fps", overrides.fps, "Frames per second of video (the physics keeps its own step)")
      ->check(CLI::Range(1, 240));
  command->add_option("--crf", overrides.crf, "H.264 constant rate factor: 0 lossless .. 51 worst; 18-23 look clean")
      ->check(CLI::Range(0, 51));
  command->add_option("--x264-preset", overrides.x264_preset,
                      "Encoder speed against file size: ultrafast (default), superfast (files 1.3-1.9x smaller, "
                      "twice the encoding time), veryfast (smaller still, slower), ... medium")
      ->check(CLI::IsMember({"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"}));
  command->add_option("--antialias", overrides.antialias,
                      "Anti-aliasing: edges (one sample a pixel, then each pixel an outline crosses mixed by its "
                      "coverage; default), msaa (multisampling, --samples of them, 4 unless said; about twice the "
                      "drawing time) or none")
      ->check(CLI::IsMember({"edges", "msaa", "none"}));
  command->add_option("--samples", overrides.samples,
                      "Multisample anti-aliasing with this many samples a pixel (same as --antialias msaa), or 0 "
                      "for none")
      ->check(CLI::IsMember({0, 2, 4, 8}));
  command->add_option("--spheres", overrides.spheres,
                      "How spheres are drawn: impostor (ray-cast, default) or tessellated (size-chosen meshes)")
      ->check(CLI::IsMember({"impostor", "tessellated"}));
  command->add_option("--shadows", overrides.shadows,
                      "Shadows: ground (on the ground only, drawn as geometry; default), map (on every body too, "
                      "from a shadow map; slower) or none")
      ->check(CLI::IsMember({"ground", "map", "none"}));
}

void add_output_options(CLI::App* command, OutputArguments& arguments, const std::string& output_help) {
  command->add_option("-o,--output", arguments.video_path, output_help);
  command->add_option("--format", arguments.format,
                      "mp4 (H.264: plays everywhere), webm (VP9: browsers, reveal.js), gif (loops; slides, "
                      "chat) or png (every frame as NAME/frame_00000.png ...: for compositing); default: by -o's "
                      "extension, else mp4")
      ->check(CLI::IsMember({"mp4", "webm", "gif", "png"}));
  command->add_flag("--transparent", arguments.transparent,
                    "No sky, no ground: the bodies, marks and overlay over a transparent background, to lay over a "
                    "slide (WebM or PNG frames: -o NAME.webm, or --format png)");
  command->add_option("--png", arguments.png_directory, "Also write frames as PNG (frame_00000.png, ...) into this directory");
  command->add_option("--frames", arguments.frames, "With --png: only these frames, numbered from 0, e.g. 0,45,90");
  command->add_option("--at", arguments.moments,
                      "With --png: stills at these moments of simulated time, in seconds (t_0.500.png, ...), "
                      "e.g. 0.5,1,2; the video's frames are then not written as PNG unless --frames says so");
  command->add_option("--layout-report", arguments.layout_report,
                      "Also write, as JSON, where each frame's overlay put each element (title, clock, captions, "
                      "legend, plots, panels, labels) and where each pane's bodies are on screen")
      ->type_name("FILE.json");
}

RenderOptions output_options(const OutputArguments& arguments, const std::string& default_path) {
  RenderOptions options;
  const std::string& path = arguments.video_path;
  const std::optional<render::VideoFormat> named = path.empty() ? std::nullopt : render::format_of_path(path);
  const render::VideoFormat of_path = named.value_or(render::VideoFormat::mp4);
  const bool frames_only = arguments.format == "png";
  if (frames_only) {
    if (named) throw std::invalid_argument("--format png writes frames into a directory: -o " + path + " names a video; give -o DIR");
    if (!arguments.png_directory.empty()) throw std::invalid_argument("--format png writes every frame into -o's directory: leave --png out");
    options.png_directory = path.empty() ? fs::path(default_path).replace_extension().string() : path;
  } else {
    if (!arguments.format.empty()) {
      options.video_format = *render::format_of_path("." + arguments.format);
      if (named && of_path != options.video_format)
        throw std::invalid_argument("-o " + path + " is a ." + render::format_name(of_path) + " file but --format says " +
                                    arguments.format + ": leave one out");
    } else {
      options.video_format = of_path;
    }
    options.video_path = !path.empty() ? path : fs::path(default_path).replace_extension(render::format_name(options.video_format)).string();
    options.png_directory = arguments.png_directory;
  }
  if (arguments.transparent && !frames_only && options.video_format != render::VideoFormat::webm)
    throw std::invalid_argument(std::string("--transparent needs WebM or PNG frames (-o NAME.webm, or --format png): ") +
                                render::format_name(options.video_format) + " keeps no alpha");
  options.renderer.transparent = arguments.transparent;
  options.layout_report_path = arguments.layout_report;
  const char* add_png = frames_only ? "" : ": add --png DIR";
  if (!arguments.frames.empty()) {
    if (options.png_directory.empty()) throw std::invalid_argument(std::string("--frames chooses PNG frames") + add_png);
    options.png_frames = parse_frames(arguments.frames);
  }
  if (!arguments.moments.empty()) {
    if (options.png_directory.empty()) throw std::invalid_argument(std::string("--at chooses PNG stills") + add_png);
    options.moments = parse_moments(arguments.moments, "--at");
  }
  if (!frames_only) {  // -o's folder too, as export's
    std::error_code error;
    if (const fs::path parent = fs::path(options.video_path).parent_path(); !parent.empty() && !fs::create_directories(parent, error) && error)
      throw render::OutputError("cannot make the folder " + parent.string() + " for " + options.video_path + ": " + error.message());
  }
  return options;
}

void read_shard(const std::string& text, int& shard, int& shards) {
  const size_t slash = text.find('/');
  try {
    shard = std::stoi(text.substr(0, slash));
    shards = std::stoi(text.substr(slash + 1));
  } catch (const std::exception&) {
    shards = 0;
  }
  if (slash == std::string::npos || shards < 1 || shards > 1000 || shard < 1 || shard > shards)
    throw std::invalid_argument("--shard wants K/N with 1 <= K <= N (like 2/4), got '" + text + "'");
}

}  // namespace impulse::demos
