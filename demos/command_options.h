// The options several commands share, each added in one place: what every command that reads a
// scene takes (--set), what every command that renders takes (--quality, --width, ...), and
// where render and compare write (-o, --png, --frames, --at, --layout-report). A new option for
// all of them is a field of SceneArguments or VideoOverrides (program.h) and a line here.
#pragma once
#include "demos/program.h"

#include <CLI/CLI.hpp>

#include <string>

namespace impulse::demos {

// The exit codes, as every command's --help ends.
extern const char* const kExitCodesHelp;
// "\nExamples:\n" and the lines, then the exit codes: a command's --help footer.
std::string examples_footer(const std::string& examples);

// --set KEY=VALUE (repeatable): render, compare, simulate, check, verify, catalogue.
void add_scene_options(CLI::App* command, SceneArguments& arguments);

// The scene options and --quality, --width, --height, --fps, --crf, --x264-preset, --antialias,
// --samples, --spheres, --shadows: every command that renders.
void add_video_options(CLI::App* command, VideoOverrides& overrides);

// Where a rendering command writes: the video, and PNG frames or stills.
struct OutputArguments {
  std::string video_path;     // -o; empty: the command's default
  std::string png_directory;  // --png
  std::string frames;         // --frames 0,45,90
  std::string moments;        // --at 0.5,1,2
  std::string layout_report;  // --layout-report FILE.json
  std::string format;         // --format mp4|webm|gif|png; empty: by -o's extension
  bool transparent = false;   // --transparent
};
// -o (with `output_help`), --format, --transparent, --png, --frames, --at, --layout-report.
void add_output_options(CLI::App* command, OutputArguments& arguments, const std::string& output_help);
// The render options they ask for: the video (at `default_path` with the format's extension, its
// directory made, when -o is not given) in the format --format or -o's extension names (MP4 when
// neither does), or with --format png every frame as PNG into -o's directory; the PNG frames and
// stills. Throws std::invalid_argument for --frames or --at without --png, a list that is not one,
// a --format that -o's extension contradicts, or --transparent where the format keeps no alpha.
RenderOptions output_options(const OutputArguments& arguments, const std::string& default_path);

// --shard K/N (catalogue, grade): 1 <= K <= N <= 1000. Throws std::invalid_argument otherwise.
void read_shard(const std::string& text, int& shard, int& shards);

}  // namespace impulse::demos
