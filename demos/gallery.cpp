#include "demos/gallery.h"

#include "demos/html_text.h"
#include "demos/film/render_scene.h"
#include "demos/page/page_export.h"
#include "demos/program.h"
#include "demos/scene/scene_file.h"
#include "physics/response_method.h"
#include "render/part_file.h"
#include "render/video_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

// The scene file's first comment lines, as one paragraph.
std::string description_of(const fs::path& scene_file) {
  std::ifstream file(scene_file);
  std::string paragraph;
  for (std::string line; std::getline(file, line);) {
    const size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string::npos || line[hash] != '#') break;
    std::string text = line.substr(hash + 1);
    text.erase(0, text.find_first_not_of(" \t"));
    if (!text.empty()) paragraph += (paragraph.empty() ? "" : " ") + text;
  }
  return paragraph;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// What the world was set to, in a line a student can read.
std::string settings_of(const Scene& scene) {
  const physics::WorldSettings& world = scene.world;
  std::string text = "method " + std::string(physics::method_name(world.method)) + ", friction " +
                     (world.contact.friction ? "on" : "off") + ", " + number(std::round(1 / world.time_step)) +
                     " steps/s, gravity " + number(world.gravity.norm()) + " m/s², " +
                     std::to_string(scene.bodies.size()) + " bodies, " + number(scene.duration) + " s simulated";
  return text;
}

const char* kStyle = R"(
body { font-family: "DejaVu Sans", sans-serif; margin: 2rem auto; max-width: 1100px; padding: 0 1rem; color: #222; background: #f4f4f6; }
h1 { font-size: 1.8rem; } h2 { font-size: 1.25rem; margin: 0 0 .5rem; }
section { background: #fff; border-radius: 10px; padding: 1rem 1.2rem; margin: 1.2rem 0; box-shadow: 0 1px 3px #0002; }
video { width: 100%; border-radius: 6px; background: #000; }
.facts, .files { font-size: .9rem; color: #555; } code { background: #eef; padding: 0 .3rem; border-radius: 3px; }
.failed { border-left: 6px solid #d55e00; }
)";

// A scene the catalogue's run did not render: its name, why (by exit code), and what to run to
// see the message; an older video, if any, follows it.
std::string failed_section(const fs::path& scene_file, int exit_code, bool older_video) {
  const std::string name = scene_file.stem().string();
  std::ostringstream section;
  section << "<section id=\"" << html(name) << "-failed\" class=\"failed\">\n<h2>" << html(name) << ": not rendered</h2>\n"
          << "<p>The last catalogue run failed on <code>" << html(scene_file.filename().string()) << "</code> (exit code "
          << exit_code << ": " << html(exit_meaning(exit_code)) << ")."
          << (older_video ? " The video below is the last one completed." : "") << " To see why: <code>impulse render "
          << html(scene_file.string()) << "</code></p>\n</section>\n";
  return section.str();
}

}  // namespace

std::string pane_video_path(const std::string& video_path, int pane) {
  return fs::path(video_path).replace_extension(".pane-" + std::to_string(pane) + ".mp4").string();
}

int write_gallery(const std::string& scenes_directory, const std::string& out_directory,
                  const std::map<std::string, int>& failed) {
  std::vector<fs::path> scene_files;
  if (fs::is_directory(scenes_directory))
    for (const auto& entry : fs::directory_iterator(scenes_directory))
      if (entry.path().extension() == ".toml") scene_files.push_back(entry.path());
  // Sections before exercises (s1_..., then ex1_...), each in name order.
  std::sort(scene_files.begin(), scene_files.end(), [](const fs::path& a, const fs::path& b) {
    const bool a_exercise = a.filename().string().rfind("ex", 0) == 0, b_exercise = b.filename().string().rfind("ex", 0) == 0;
    return a_exercise != b_exercise ? b_exercise : a < b;
  });

  std::ostringstream page;
  page << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<title>impulse: lecture videos</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
       << "<h1>Impulse response: lecture videos</h1>\n"
       << "<p>Rigid-body collision physics, one video per section and exercise of the workshop. Each video has "
          "captions (CC) and chapters at its impacts; a comparison shows its settings side by side.</p>\n";
  int videos = 0;
  for (const fs::path& scene_file : scene_files) {
    const std::string name = scene_file.stem().string();
    const fs::path video = fs::path(out_directory) / (name + ".mp4");
    const bool has_video = fs::is_regular_file(video);
    // A scene whose checks failed has its video; any other failure has none from this run.
    if (const auto failure = failed.find(scene_file.filename().string());
        failure != failed.end() && (failure->second != kExitCheckFailed || !has_video))
      page << failed_section(scene_file, failure->second, has_video);
    if (!has_video) continue;
    Scene scene;
    try {
      scene = load_scene(scene_file.string());
    } catch (const SceneError&) {
      continue;  // the catalogue has said what is wrong with it
    }
    const render::VideoFacts facts = render::probe_video(video.string());
    ++videos;
    auto beside = [&](const std::string& path) { return fs::is_regular_file(path) ? fs::path(path).filename().string() : ""; };
    const std::string poster = beside(poster_path(video.string()));
    const std::string captions = beside(captions_path(video.string()));
    const std::string chapters = beside(chapters_path(video.string()));
    const std::string interactive = beside(page_path(video.string()));
    page << "<section id=\"" << html(name) << "\">\n<h2>" << html(scene.title.empty() ? name : scene.title) << "</h2>\n"
         << "<video controls preload=\"metadata\"" << (poster.empty() ? "" : " poster=\"" + html(poster) + "\"")
         << " data-width=\"" << facts.width << "\" data-height=\"" << facts.height << "\" data-duration=\""
         << number(facts.duration) << "\">\n<source src=\"" << html(name) << ".mp4\" type=\"video/mp4\">\n";
    if (!captions.empty())
      page << "<track kind=\"captions\" src=\"" << html(captions) << "\" srclang=\"en\" label=\"Captions\">\n";
    if (!chapters.empty())
      page << "<track kind=\"chapters\" src=\"" << html(chapters) << "\" srclang=\"en\" label=\"Chapters\">\n";
    page << "</video>\n<p>" << html(description_of(scene_file)) << "</p>\n";
    page << "<p class=\"facts\">" << facts.width << "×" << facts.height << ", " << number(std::round(facts.duration * 10) / 10)
         << " s of video. Settings: " << html(settings_of(scene));
    if (!facts.comment.empty()) page << "; changed: <code>" << html(facts.comment) << "</code>";
    page << ".</p>\n";
    if (!scene.compare.values.empty()) {
      page << "<p class=\"facts\">Side by side, " << html(scene.compare.key) << ":";
      for (size_t i = 0; i < scene.compare.values.size(); ++i) {
        const std::string alone = beside(pane_video_path(video.string(), int(i) + 1));
        page << (i ? " · " : " ");
        if (alone.empty()) {
          page << html(scene.compare.labels[i]);
        } else {
          page << "<a href=\"" << html(alone) << "\">" << html(scene.compare.labels[i]) << "</a>";
        }
      }
      page << " (each link: that pane alone).</p>\n";
    }
    if (!interactive.empty())
      page << "<p class=\"files\"><a href=\"" << html(interactive) << "\">The interactive page</a>: the same run to play, scrub "
           << "and orbit in the browser, and each body's numbers on a click.</p>\n";
    page << "<p class=\"files\">Render it yourself: <code>impulse render " << html(scene_file.string()) << "</code>";
    if (!captions.empty()) page << " · <a href=\"" << html(captions) << "\">captions</a>";
    if (!chapters.empty()) page << " · <a href=\"" << html(chapters) << "\">chapters</a>";
    page << "</p>\n</section>\n";
  }
  page << "</body>\n</html>\n";

  const std::string path = (fs::path(out_directory) / "index.html").string();
  render::PartFile part(path);
  {
    std::ofstream file(part.part_path(), std::ios::binary);
    file << page.str();
    file.close();
    if (!file) throw render::OutputError("cannot write " + part.part_path());
  }
  part.commit();
  return videos;
}

}  // namespace impulse::demos
