#include "demos/film/layout_report.h"

#include <toml++/toml.h>

#include <cmath>
#include <sstream>

namespace impulse::demos {
namespace {

// As JSON writes a string: quoted, with quotes, backslashes and control characters escaped.
std::string quoted(const std::string& text) {
  std::ostringstream out;
  out << toml::json_formatter{toml::value<std::string>{text}};
  return out.str();
}

// The whole pixels covering `box` (a far edge a thousandth of a pixel over a line stays on it).
std::string pixels(const render::ScreenBox& box) {
  const long x = std::lround(std::floor(box.x + 1e-3f)), y = std::lround(std::floor(box.y + 1e-3f));
  const long right = std::lround(std::ceil(box.right() - 1e-3f)), bottom = std::lround(std::ceil(box.bottom() - 1e-3f));
  return "\"x\": " + std::to_string(x) + ", \"y\": " + std::to_string(y) + ", \"w\": " + std::to_string(right - x) +
         ", \"h\": " + std::to_string(bottom - y);
}

}  // namespace

LayoutReport::LayoutReport(const std::string& path, int width, int height) : part_(path), file_(part_.part_path()) {
  if (!file_) throw render::OutputError("cannot write " + part_.part_path());
  file_ << "{\"width\": " << width << ", \"height\": " << height << ", \"frames\": [";
}

void LayoutReport::add(int frame, const render::PaintedLayout& layout, const std::vector<render::OverlayBody>& bodies) {
  file_ << (first_frame_ ? "\n" : ",\n") << "{\"frame\": " << frame << ", \"elements\": [";
  first_frame_ = false;
  for (size_t i = 0; i < layout.elements.size(); ++i)
    file_ << (i ? ", " : "") << "{\"name\": " << quoted(layout.elements[i].name) << ", " << pixels(layout.elements[i].box) << "}";
  file_ << "], \"dropped\": [";
  for (size_t i = 0; i < layout.dropped.size(); ++i) file_ << (i ? ", " : "") << quoted(layout.dropped[i]);
  file_ << "], \"bodies\": [";
  for (size_t i = 0; i < bodies.size(); ++i)
    file_ << (i ? ", " : "") << "{\"pane\": " << bodies[i].pane << ", \"name\": " << quoted(bodies[i].name)
          << ", \"moving\": " << (bodies[i].moving ? "true" : "false") << ", " << pixels(bodies[i].box) << "}";
  file_ << "]}";
}

void LayoutReport::commit() {
  file_ << "\n]}\n";
  file_.close();
  if (!file_) throw render::OutputError("cannot write " + part_.part_path());
  part_.commit();
}

}  // namespace impulse::demos
