// `impulse export`: a scene into its interactive page, one HTML file that plays anywhere offline.
// `impulse preview`: the same page served on 127.0.0.1, made again whenever the scene is saved.
#include "demos/command.h"
#include "demos/command_options.h"
#include "demos/page/page_export.h"
#include "demos/page/page_glb.h"
#include "demos/page/page_preview.h"
#include "demos/program.h"
#include "render/part_file.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

namespace impulse::demos {
namespace {

struct ExportArguments {
  std::string scene_path;
  std::string out_path;  // -o; empty: out/NAME.html (or .glb)
  std::string format;    // html or glb; empty: glb where -o ends in .glb, else html
  bool marks = false;    // glb: the video's arrows too (the page always has them)
  SceneArguments scene;
};

int export_page(const ExportArguments& arguments) {
  namespace fs = std::filesystem;
  std::string format = arguments.format;
  if (format.empty()) format = fs::path(arguments.out_path).extension() == ".glb" ? "glb" : "html";
  const std::string script = format == "html" ? page_script() : "";
  const std::string path = arguments.out_path.empty()
                               ? (fs::path("out") / fs::path(arguments.scene_path).stem()).string() + "." + format
                               : arguments.out_path;
  render::write_file(path, [&](std::ostream& out) {
    if (format == "glb") write_glb(load(SceneFile(arguments.scene_path), arguments.scene, false), out, arguments.marks);
    else write_page(load_panes(arguments.scene_path, arguments.scene).panes, script, out);
  });
  std::fprintf(stderr, "wrote %s\n", path.c_str());
  return 0;
}

const std::string kExportFooter =
    "\nThe page holds the scene's run (each video frame's poses, marks and equations) and its viewer\n"
    "(three.js): open it from disk in any browser, offline; play, pause, scrub, step a frame, change the\n"
    "speed, orbit (drag), zoom (wheel) and pan (right drag) from the scene's camera, click a body for its\n"
    "numbers. A scene with [compare] shows its panes side by side, as its video does.\n"
    "With --format glb (or -o NAME.glb) it writes the run as glTF 2.0 instead, for Blender (File >\n"
    "Import > glTF 2.0), three.js and other 3D tools: a node and mesh per body in its colour, the rods,\n"
    "the scene's camera, and an animation \"run\" of their poses at the video's frames; with --marks\n"
    "also the video's arrows (contact normals, impulses, friction, velocities) under a node \"marks\".\n" +
    examples_footer("  impulse export assets/scenes/bounce.toml                # out/bounce.html\n"
                    "  impulse export assets/scenes/s5_half_pipe.toml -o half_pipe.html\n"
                    "  impulse export scene.toml --set body[ball].restitution=0.5 -o bouncier.html\n"
                    "  impulse export assets/scenes/ex5_newtons_cradle.toml --format glb   # out/ex5_newtons_cradle.glb\n"
                    "  impulse export assets/scenes/bounce.toml --format glb --marks       # with the video's arrows\n");

}  // namespace

void add_export_command(Commands& commands) {
  auto arguments = std::make_shared<ExportArguments>();
  CLI::App* command = commands.add("export", "Write a scene's interactive page: one HTML file to play and orbit in a browser (or a glTF file)",
                                   kExportFooter, [arguments](const Invocation&) { return export_page(*arguments); });
  command->add_option("scene", arguments->scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  command->add_option("-o,--output", arguments->out_path, "The page (.html) or glTF file (.glb); default out/NAME.html or out/NAME.glb");
  command->add_option("--format", arguments->format, "html (the page) or glb (glTF 2.0 binary); default: glb where -o ends in .glb, else html")
      ->check(CLI::IsMember({"html", "glb"}));
  command->add_flag("--marks", arguments->marks,
                    "glb: also the video's arrows (contact normals, impulses, friction, velocities) under a node \"marks\"; "
                    "the html page always has them");
  add_scene_options(command, arguments->scene);
}

namespace {

struct PreviewArguments {
  std::string scene_path;
  int port = 8765;
  SceneArguments scene;
};

const std::string kPreviewFooter =
    "\nServes the scene's page on this computer only (127.0.0.1) and prints its address: open it in a\n"
    "browser beside your editor. Each time the scene file is saved it is simulated again and the page\n"
    "shows the new run from the same camera and moment; an error in the scene shows in the page with\n"
    "its file, line and field, over the last run that read. Ctrl-C stops it. Render the video once\n"
    "the scene is right.\n" +
    examples_footer("  impulse preview assets/scenes/bounce.toml              # http://127.0.0.1:8765/\n"
                    "  impulse preview my_scene.toml --port 9000\n"
                    "  impulse preview my_scene.toml --port 0                 # any free port\n");

}  // namespace

void add_preview_command(Commands& commands) {
  auto arguments = std::make_shared<PreviewArguments>();
  CLI::App* command = commands.add("preview", "Serve a scene's page on 127.0.0.1, simulated again each time the file is saved",
                                   kPreviewFooter, [arguments](const Invocation&) {
                                     const std::string script = page_script();
                                     const PreviewArguments& a = *arguments;
                                     serve_preview(
                                         a.scene_path, a.port, script,
                                         [&a] {
                                           std::ostringstream run;
                                           write_run_json(load_panes(a.scene_path, a.scene).panes, run);
                                           return run.str();
                                         },
                                         [&a](const std::string& address) {
                                           std::printf("impulse preview: %s shows %s (saving it simulates again; Ctrl-C stops)\n",
                                                       address.c_str(), a.scene_path.c_str());
                                           std::fflush(stdout);
                                         });
                                     return 0;
                                   });
  command->add_option("scene", arguments->scene_path, "Scene file (.toml)")->required()->check(CLI::ExistingFile);
  command->add_option("--port", arguments->port, "The port on 127.0.0.1 (0: any free one)")->capture_default_str()->check(CLI::Range(0, 65535));
  add_scene_options(command, arguments->scene);
}

}  // namespace impulse::demos
