#include "demos/verify_report.h"

#include <filesystem>
#include <fstream>

#include "demos/html_text.h"
#include "demos/film/moments.h"
#include "render/part_file.h"

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

// Relative to the report, so that the directory can be moved or kept as an artefact.
std::string link(const std::string& report_path, const std::string& image) {
  return html(fs::path(image).lexically_relative(fs::path(report_path).parent_path()).string());
}

void write_moment(std::ofstream& page, const std::string& path, const MomentReport& moment) {
  page << "<section class=\"" << (moment.passed ? "pass" : "fail") << "\">\n<h2>t = "
       << moment_name(moment.time).substr(2) << " s: " << (moment.passed ? "matches" : "DIFFERS") << "</h2>\n<ul>\n";
  for (const std::string& line : moment.lines) page << "<li>" << html(line) << "</li>\n";
  page << "</ul>\n";
  if (!moment.strip.empty()) {
    page << "<p>golden | actual | diff (red: differs; pink: differs faintly; yellow: an anti-aliased edge, forgiven)</p>\n<a href=\""
         << link(path, moment.strip) << "\"><img src=\"" << link(path, moment.strip) << "\" alt=\"golden, actual, diff\"></a>\n";
  } else if (!moment.actual.empty()) {
    page << "<p>actual</p>\n<img src=\"" << link(path, moment.actual) << "\" alt=\"actual\">\n";
  } else if (!moment.golden.empty()) {
    page << "<img src=\"" << link(path, moment.golden) << "\" alt=\"golden\" class=\"small\">\n";
  }
  page << "</section>\n";
}

}  // namespace

void write_report(const std::string& path, const std::string& scene_path, const GoldenManifest& manifest, bool passed,
                  const std::vector<std::string>& notes, const std::vector<MomentReport>& moments) {
  int failed = 0;
  for (const MomentReport& moment : moments) failed += !moment.passed;
  render::PartFile part(path);
  {
    std::ofstream page(part.part_path());
    page << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>impulse verify: "
         << html(scene_path) << "</title>\n<style>body{font-family:sans-serif;margin:2em;max-width:100%}"
         << ".pass h2{color:#009E73}.fail h2{color:#D55E00}img{max-width:100%}img.small{max-width:320px}"
         << "td{padding:0 1em 0 0}</style></head><body>\n<h1>impulse verify: " << html(scene_path) << "</h1>\n"
         << "<p><b>" << (passed ? "passed" : "FAILED") << "</b>: " << moments.size() - failed << " of "
         << moments.size() << " moments match.</p>\n";
    for (const std::string& note : notes) page << "<p><b>" << html(note) << "</b></p>\n";
    page << "<table><tr><td>goldens</td><td>" << html(describe_size(manifest)) << ", anti-aliasing " << html(manifest.antialias)
         << (manifest.antialias == "msaa" ? " (" + std::to_string(manifest.samples) + " samples)" : std::string())
         << ", spheres " << html(manifest.spheres) << ", shadows " << html(manifest.shadows) << "</td></tr>\n"
         << "<tr><td>recorded by</td><td>" << html(manifest.program) << " from " << html(manifest.scene) << "</td></tr>\n"
         << "<tr><td>--set</td><td>";
    for (const std::string& setting : manifest.settings) page << "<code>" << html(setting) << "</code> ";
    page << "</td></tr></table>\n";
    for (const MomentReport& moment : moments) write_moment(page, path, moment);
    page << "</body></html>\n";
    page.close();
    if (!page) throw render::OutputError("cannot write " + part.part_path());
  }
  part.commit();
}

}  // namespace impulse::demos
