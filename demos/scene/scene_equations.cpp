// [[equation]] tables (equation_cue.h). Only what can be told without LaTeX is checked here (the
// loader runs no program: it stays quick for `check`, the bad-scene tests and the fuzzer); the
// TeX itself is typeset and checked by the film's check_equations (demos/film/live_equations.h).
#include "demos/scene/scene_sections.h"

namespace impulse::demos {

namespace {

// TOML reads \t, \r, \n, \f and \b in double quotes as escapes: tex = "\theta" arrives as a tab
// and "heta", "\frac" as a form feed and "rac". LaTeX needs none of those characters; single
// quotes keep every backslash.
void check_latex_quotes(TableReader& r, std::string_view key, const std::string& tex) {
  const toml::node* node = r.get(key);
  const char quotes = r.quotes(node);
  if (quotes == '\'') return;
  for (const char c : tex) {
    const char* escape = c == '\t' ? "\\t" : c == '\r' ? "\\r" : c == '\f' ? "\\f" : c == '\b' ? "\\b"
                       : c == '\n' && quotes == '"' ? "\\n" : nullptr;
    if (escape)
      r.fail(node, key, std::string("TOML read ") + escape + " in double quotes as a control character (tex = \"\\theta\" becomes a tab "
                        "and 'heta'): write LaTeX in single quotes, tex = '\\theta'");
  }
}

}  // namespace

void read_equations(TableReader& top, Scene& scene) {
  const toml::array* equations = top.table_list("equation");
  if (!equations) return;
  int number = 0;
  for (const toml::node& item : *equations) {
    const std::string where = "[[equation]] " + std::to_string(++number);
    TableReader r = top.child(*item.as_table(), where);
    EquationCue cue;
    cue.tex = r.string("tex", "");
    if (cue.tex.find_first_not_of(" \t\r\n") == std::string::npos)
      r.fail(r.get("tex"), "tex", "missing: LaTeX mathematics in single quotes, like tex = 'J = \\frac{1}{2}'");
    check_latex_quotes(r, "tex", cue.tex);
    cue.origin = r.where(r.get("tex"), "tex");
    cue.live = has_live_values(cue.tex);
    if (cue.live && !(scene.playback.slow_motion_impulse > 0))
      r.fail(r.get("tex"), "tex",
             "live values such as {e} are those of the latest impact that slows the video: set [playback] "
             "slow_motion_impulse > 0");
    cue.start = r.number("start", 0, 0);
    cue.end = r.number("end", scene.duration, 0);
    if (cue.end <= cue.start) r.fail(r.get("end"), "end", "must come after start");
    cue.position = r.choice("position", cue.position, {"top-left", "top-right", "bottom-left", "bottom-right", "bottom"});
    cue.size = r.number("size", cue.size, 6, 100);
    const int panes = int(scene.compare.values.size());
    if (panes == 0 && names_the_pane(cue.tex))
      r.fail(r.get("tex"), "tex", "names a pane's {value} or {label}, but the scene has no [compare] table, so no panes");
    cue.pane = r.integer("pane", 0, 0, 4);
    if (cue.pane > panes)
      r.fail(r.get("pane"), "pane", panes == 0 ? "the scene has no [compare] table, so no panes"
                                              : "the [compare] table has " + std::to_string(panes) + " panes");
    r.finish();
    scene.equations.push_back(std::move(cue));
  }
}

}  // namespace impulse::demos
