// The command line itself: options after the subcommand; every command's --help with examples and
// exit codes.
#include "demos/program.h"
#include "tests/program/in_process.h"
#include "tests/program/program_test_files.h"
#include "tests/support/video_decode.h"
#include "render/gl_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace impulse {
namespace {

using namespace testing;

TEST(Cli, OptionsWorkAfterTheSubcommandAndHelpShowsExamplesAndExitCodes) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  EXPECT_TRUE(run_in_process({"check", (dir / "slide.toml").string(), "-q"}).succeeded());
  for (const char* command : {"render", "compare", "simulate", "check", "verify", "catalogue", "gallery"}) {
    const testing::ProgramRun help = run_in_process({command, "--help"});
    EXPECT_TRUE(help.succeeded()) << command;
    EXPECT_NE(help.stdout_text.find("Examples:\n  impulse " + std::string(command)), std::string::npos) << help.stdout_text;
    EXPECT_NE(help.stdout_text.find("Exit codes: 0 "), std::string::npos) << help.stdout_text;
  }
  const testing::ProgramRun none = run_in_process({});
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.stderr_text.find("A subcommand is required"), std::string::npos) << none.stderr_text;
  const testing::ProgramRun unknown = run_in_process({"frobnicate"});
  EXPECT_EQ(unknown.exit_code, 1) << unknown.describe();
}

// --version names the commit and what OpenGL draws with here; --gl and --gpu choose it (through
// the environment, so the program's child processes draw the same way); a backend or GPU that is
// not there is refused in words.
TEST(Cli, VersionSaysWhatDrawsAndGlChoosesIt) {
  struct Kept {  // the test process's IMPULSE_GL and IMPULSE_GPU, as they were
    std::vector<std::pair<std::string, std::optional<std::string>>> values;
    Kept() {
      for (const char* name : {"IMPULSE_GL", "IMPULSE_GPU"}) {
        const char* value = std::getenv(name);
        values.emplace_back(name, value ? std::optional<std::string>(value) : std::nullopt);
      }
    }
    ~Kept() {
      for (const auto& [name, value] : values) value ? setenv(name.c_str(), value->c_str(), 1) : unsetenv(name.c_str());
    }
  } kept;
  unsetenv("IMPULSE_GL");
  unsetenv("IMPULSE_GPU");
  const ProgramRun version = run_in_process({"--version"});
  ASSERT_TRUE(version.succeeded()) << version.describe();
  EXPECT_EQ(version.stdout_text.rfind("impulse (commit ", 0), 0u) << version.stdout_text;
  EXPECT_NE(version.stdout_text.find("OpenGL: egl, "), std::string::npos) << "auto prefers EGL: " << version.stdout_text;
  EXPECT_NE(version.stdout_text.find("4.5 (Core Profile)"), std::string::npos) << version.stdout_text;
  if (render::osmesa_built()) {
    const ProgramRun osmesa = run_in_process({"--gl", "osmesa", "--version"});
    EXPECT_NE(osmesa.stdout_text.find("OpenGL: osmesa, OSMesa: llvmpipe"), std::string::npos) << osmesa.describe();
    EXPECT_STREQ(std::getenv("IMPULSE_GL"), "osmesa") << "set for the program's child processes";
  }
  const ProgramRun unknown = run_in_process({"--gl", "vulkan", "--version"});
  EXPECT_EQ(unknown.exit_code, 1) << unknown.describe();
  EXPECT_NE(unknown.stderr_text.find("auto,egl,osmesa"), std::string::npos) << unknown.stderr_text;
  const ProgramRun gpu = run_in_process({"--gl", "egl", "--gpu", "200", "--version"});
  EXPECT_NE(gpu.stdout_text.find("OpenGL: none works here: EGL: no GPU 200"), std::string::npos) << gpu.describe();
}

// A video's format comes from -o's extension or --format: the same frames as MP4, WebM and GIF,
// or as PNG files into a directory; an extension and a --format that disagree are refused, and
// nothing is written.
TEST(Cli, FormatComesFromTheExtensionOrFormatAndContradictionsAreRefused) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  auto render = [&](std::vector<std::string> options) {
    std::vector<std::string> arguments = {"-q", "render", (dir / "slide.toml").string(), "--width", "64", "--height", "48", "--fps", "5"};
    arguments.insert(arguments.end(), options.begin(), options.end());
    return run_in_process(arguments);
  };
  size_t frames = 0;
  for (const char* name : {"a.mp4", "a.webm", "a.gif"}) {
    const ProgramRun run = render({"-o", (dir / name).string()});
    ASSERT_TRUE(run.succeeded()) << name << ": " << run.describe();
    const testing::DecodedVideo video = testing::decode_video((dir / name).string());
    EXPECT_EQ(video.width, 64) << name;
    if (frames == 0) frames = video.frames.size();
    EXPECT_EQ(video.frames.size(), frames) << name;
  }
  EXPECT_GT(frames, 5u);
  const ProgramRun named = render({"--format", "webm", "-o", (dir / "b.video").string()});
  ASSERT_TRUE(named.succeeded()) << named.describe();
  EXPECT_EQ(testing::decode_video((dir / "b.video").string()).frames.size(), frames) << "--format over an unknown extension";
  const ProgramRun png = render({"--format", "png", "-o", (dir / "frames").string()});
  ASSERT_TRUE(png.succeeded()) << png.describe();
  size_t pngs = 0;
  for (const auto& entry : fs::directory_iterator(dir / "frames")) pngs += entry.path().extension() == ".png";
  EXPECT_EQ(pngs, frames);
  // --transparent: WebM keeps the alpha, no sky or ground in it; a format without alpha is refused.
  const ProgramRun clear = render({"--transparent", "-o", (dir / "clear.webm").string()});
  ASSERT_TRUE(clear.succeeded()) << clear.describe();
  const testing::DecodedVideo over_a_slide = testing::decode_video((dir / "clear.webm").string());
  ASSERT_EQ(over_a_slide.frames.size(), frames);
  int transparent = 0, opaque = 0;
  for (size_t i = 3; i < over_a_slide.frames.back().rgba.size(); i += 4) {
    transparent += over_a_slide.frames.back().rgba[i] <= 4;
    opaque += over_a_slide.frames.back().rgba[i] >= 251;
  }
  EXPECT_GT(transparent, 64 * 48 / 2) << "sky and ground left out";
  EXPECT_GT(opaque, 20) << "the bodies and the overlay";
  for (const auto& [options, words] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--format", "gif", "-o", (dir / "c.mp4").string()}, "is a .mp4 file but --format says gif"},
           {{"--format", "png", "-o", (dir / "c.gif").string()}, "give -o DIR"},
           {{"--format", "png", "--png", (dir / "d").string(), "-o", (dir / "e").string()}, "leave --png out"},
           {{"--transparent", "-o", (dir / "c.mp4").string()}, "--transparent needs WebM or PNG frames"}}) {
    const ProgramRun refused = render(options);
    EXPECT_EQ(refused.exit_code, 1) << refused.describe();
    EXPECT_NE(refused.stderr_text.find(words), std::string::npos) << refused.stderr_text;
  }
  EXPECT_FALSE(fs::exists(dir / "c.mp4") || fs::exists(dir / "c.gif") || fs::exists(dir / "d") || fs::exists(dir / "e"));
}

// --antialias chooses; --samples alone still means multisampling; the two saying different things
// are refused before anything is drawn.
TEST(Cli, AntialiasAndSamplesChooseTheAntiAliasingAndContradictionsAreRefused) {
  const fs::path dir = work_directory();
  std::ofstream(dir / "slide.toml") << kSlide;
  const std::string scene = (dir / "slide.toml").string();
  auto render = [&](const std::string& name, std::vector<std::string> options) {
    std::vector<std::string> arguments = {"-q", "render", scene, "--width", "64", "--height", "48", "--fps", "5",
                                          "-o", (dir / name).string()};
    arguments.insert(arguments.end(), options.begin(), options.end());
    return run_in_process(arguments);
  };
  for (const auto& [name, options] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"edges.mp4", {}}, {"msaa.mp4", {"--antialias", "msaa"}}, {"eight.mp4", {"--samples", "8"}},
           {"none.mp4", {"--antialias", "none"}}, {"zero.mp4", {"--samples", "0"}}}) {
    const ProgramRun run = render(name, options);
    EXPECT_TRUE(run.succeeded()) << name << ": " << run.describe();
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  }
  const ProgramRun contradiction = render("refused.mp4", {"--antialias", "edges", "--samples", "4"});
  EXPECT_EQ(contradiction.exit_code, 1) << contradiction.describe();
  EXPECT_NE(contradiction.stderr_text.find("--samples"), std::string::npos) << contradiction.stderr_text;
  EXPECT_NE(contradiction.stderr_text.find("--antialias msaa"), std::string::npos) << contradiction.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "refused.mp4"));
  // What each choice gives the renderer.
  auto chosen = [](const std::string& antialias, std::optional<int> samples) {
    demos::VideoOverrides overrides;
    overrides.antialias = antialias;
    overrides.samples = samples;
    demos::Scene any_scene;
    demos::RenderOptions options;
    overrides.apply(any_scene, options);
    return options.renderer;
  };
  using render::Antialiasing;
  EXPECT_EQ(chosen("", std::nullopt).antialiasing, Antialiasing::edges);
  EXPECT_EQ(chosen("msaa", std::nullopt).antialiasing, Antialiasing::msaa);
  EXPECT_EQ(chosen("msaa", std::nullopt).samples, 4);
  EXPECT_EQ(chosen("", 8).antialiasing, Antialiasing::msaa);
  EXPECT_EQ(chosen("msaa", 2).samples, 2);
  EXPECT_EQ(chosen("", 0).antialiasing, Antialiasing::none);
  EXPECT_EQ(chosen("none", std::nullopt).antialiasing, Antialiasing::none);
  EXPECT_EQ(chosen("edges", std::nullopt).antialiasing, Antialiasing::edges);
  const ProgramRun unknown = render("unknown.mp4", {"--antialias", "fxaa"});
  EXPECT_EQ(unknown.exit_code, 1) << unknown.describe();
  EXPECT_NE(unknown.stderr_text.find("--antialias"), std::string::npos) << unknown.stderr_text;
}

}  // namespace
}  // namespace impulse
