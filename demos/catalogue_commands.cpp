// `impulse catalogue` and `impulse gallery`: every scene of a directory into videos, and the page
// that shows them.
#include "demos/catalogue.h"
#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/gallery.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace impulse::demos {
namespace {

// The catalogue that came with the program, so that `impulse catalogue` works from any directory:
// <prefix>/share/impulse/scenes beside an installed <prefix>/bin/impulse (cmake --install, the
// .deb), else the source tree's assets/scenes (the program of a build tree).
std::string catalogue_scenes() {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed = self.parent_path().parent_path() / "share" / "impulse" / "scenes";
    if (fs::is_directory(installed, error)) return installed.string();
  }
  // From the source tree's root, the name a user types, which the messages then say.
  if (fs::equivalent("assets/scenes", IMPULSE_SOURCE_SCENES, error)) return "assets/scenes";
  return IMPULSE_SOURCE_SCENES;
}

struct CatalogueArguments {
  std::string scenes_directory = catalogue_scenes(), out_directory = "out";
  std::string shard;
  CatalogueChoice choice;
  VideoOverrides overrides;
};

struct GalleryArguments {
  std::string scenes_directory = catalogue_scenes(), out_directory = "out";
};

const std::string kCatalogueFooter = examples_footer(
    "  impulse catalogue -o out\n"
    "  impulse catalogue --scenes my_course/ -o videos/ --quality low\n"
    "  impulse catalogue --shard 2/4 -o out     # the second of four CI jobs\n"
    "  impulse catalogue --changed-only -o out  # only scenes edited since their video\n"
    "  impulse catalogue --jobs 2 -o out        # two scenes at once\n");

const std::string kGalleryFooter =
    "\nThe catalogue writes it too, after its videos. It works opened from disk and served by any\n"
    "static server.\n" +
    examples_footer("  impulse gallery -o out && xdg-open out/index.html\n"
                    "  impulse gallery --scenes my_course/ -o videos/ && python3 -m http.server -d videos\n");

}  // namespace

void add_catalogue_command(Commands& commands) {
  auto arguments = std::make_shared<CatalogueArguments>();
  CLI::App* catalogue = commands.add(
      "catalogue", "Render every scene of a directory into videos", kCatalogueFooter, [arguments](const Invocation& run) {
        CatalogueChoice choice = arguments->choice;
        if (!arguments->shard.empty()) read_shard(arguments->shard, choice.shard, choice.shards);
        choice.child_arguments = job_arguments(run.arguments);
        return render_catalogue(arguments->scenes_directory, arguments->out_directory, run.progress, arguments->overrides,
                                choice);
      });
  catalogue->add_option("--scenes", arguments->scenes_directory, "Directory of scene files")->capture_default_str();
  catalogue->add_option("-o,--output", arguments->out_directory, "Directory for the videos")->capture_default_str();
  catalogue
      ->add_option("--shard", arguments->shard, "K/N: render only every Nth scene in name order, from the Kth (CI jobs in parallel)")
      ->type_name("K/N");
  catalogue->add_option("--jobs", arguments->choice.jobs, "Scenes rendered at once, each in a process of its own (default 1)")
      ->check(CLI::Range(1, 16));
  catalogue->add_option("--only", arguments->choice.only, "")->group("");  // one job of --jobs
  catalogue->add_flag("--changed-only", arguments->choice.changed_only,
                      "Skip a scene whose video is newer than its scene file and the program (not after --set or --quality changes)");
  add_video_options(catalogue, arguments->overrides);
}

void add_gallery_command(Commands& commands) {
  auto arguments = std::make_shared<GalleryArguments>();
  CLI::App* gallery = commands.add(
      "gallery", "Write OUT/index.html: every video of the catalogue, for students", kGalleryFooter,
      [arguments](const Invocation&) {
        const std::string& out = arguments->out_directory;
        if (!std::filesystem::is_directory(out))
          throw std::invalid_argument("no video directory '" + out + "' (render the catalogue first)");
        const int videos = write_gallery(arguments->scenes_directory, out);
        std::fprintf(stderr, "wrote %s/index.html (%d videos)\n", out.c_str(), videos);
        return 0;
      });
  gallery->add_option("--scenes", arguments->scenes_directory, "Directory of the scene files the videos were made from")
      ->capture_default_str();
  gallery->add_option("-o,--output", arguments->out_directory, "Directory of the videos; index.html goes there")
      ->capture_default_str();
}

}  // namespace impulse::demos
