// [[equation]]: LaTeX mathematics shown from `start` to `end` seconds of simulated time, in a
// corner of the frame, with live values of the latest impact that slows the video filled in
// (docs/scene_files.md). The scene only reads it; the film typesets it (demos/film/
// live_equations.h), and a LaTeX error is reported with `origin`, the file and line of its `tex`.
#pragma once
#include <string>
#include <string_view>

namespace impulse::demos {

struct EquationCue {
  std::string tex;        // LaTeX math mode, e.g. "J = \frac{-(1+e)\,v_{ab}\cdot\hat n}{1/m_a + 1/m_b}"
  double start = 0;       // s
  double end = 1e9;       // s
  std::string position = "top-right";  // top-left, top-right, bottom-left, bottom-right, bottom
  double size = 20;       // the letters' size, pixels at 720 lines (the frame's height scales it)
  std::string origin;     // "FILE:LINE: [[equation]] N field 'tex'" (or the --set argument)
  bool live = false;      // `tex` holds live values: shown from the first impact on
  int pane = 0;           // in a comparison ([compare]), the pane (from 1) that shows it; 0: every pane
};

// The live values a brace group may hold: "{e}" becomes the impact's restitution, written with
// three significant figures (README.md lists what each is).
inline constexpr std::string_view kLiveValueNames[] = {"t", "e", "vab", "ma", "mb", "ang", "ra", "rb", "J", "Jsolver"};

// Whether `tex` holds a brace group that is exactly a live value's name, e.g. "{e}" (not "\{e}").
inline bool has_live_values(std::string_view tex) {
  for (size_t open = tex.find('{'); open != std::string_view::npos; open = tex.find('{', open + 1)) {
    const size_t close = tex.find('}', open);
    if (close == std::string_view::npos) return false;
    if (open > 0 && tex[open - 1] == '\\') continue;
    for (std::string_view name : kLiveValueNames)
      if (tex.substr(open + 1, close - open - 1) == name) return true;
  }
  return false;
}

}  // namespace impulse::demos
