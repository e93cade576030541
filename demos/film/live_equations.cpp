#include "demos/film/live_equations.h"

#include "demos/film/captions.h"
#include "demos/film/marks.h"
#include "demos/scene/scene_error.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

namespace impulse::demos {
namespace {

constexpr float kPanelSize = 16;      // pixels at 720 lines: eq. 8's letters (as its heading's), in a pane
constexpr float kWidePanelSize = 18;  // eq. 13's, whose long denominator needs them larger

// Three significant figures, as labels write them; a value that rounds to zero is "0.00", not "-0.00".
std::string figures(double value) {
  std::string text = render::three_figures(value);
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

std::string vector_figures(const physics::Vec3& v) {
  std::string text = "(";  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) about that
  text += figures(v.x()) + ",\\," + figures(v.y()) + ",\\," + figures(v.z()) + ")";
  return text;
}

// "1/2.00", or 0 for a static body (its inverse mass).
std::string inverse_mass(double inverse) { return inverse > 0 ? "1/" + figures(1 / inverse) : "0"; }

double eq13_impulse(const ImpactNumbers& impact) {
  const double denominator = impact.inverse_mass_a + impact.inverse_mass_b + impact.angular;
  return denominator > 0 ? -(1 + impact.restitution) * impact.point_approach / denominator : 0;
}

std::map<std::string, std::string> live_values(const ImpactNumbers& impact) {
  auto mass = [](double inverse) { return inverse > 0 ? figures(1 / inverse) : std::string("\\infty"); };
  return {{"t", figures(impact.time)},
          {"e", figures(impact.restitution)},
          {"vab", figures(impact.point_approach)},
          {"ma", mass(impact.inverse_mass_a)},
          {"mb", mass(impact.inverse_mass_b)},
          {"ang", figures(impact.angular)},
          {"ra", vector_figures(impact.offset_a)},
          {"rb", vector_figures(impact.offset_b)},
          {"J", figures(eq13_impulse(impact))},
          {"Jsolver", figures(impact.impulse)}};
}

// Numbers of the right kind for checking an equation's TeX before any impact.
ImpactNumbers made_up_impact() {
  ImpactNumbers impact;
  impact.time = 0.5;
  impact.approach = impact.point_approach = -3;
  impact.restitution = 0.5;
  impact.inverse_mass_a = 1;
  impact.inverse_mass_b = 0.5;
  impact.offset_a = physics::Vec3(0.5, 0.25, 0);
  impact.angular = 0.25;
  impact.impulse = 2;
  return impact;
}

render::PanelPlace place_named(const std::string& position) {
  if (position == "top-left") return render::PanelPlace::top_left;
  if (position == "bottom-left") return render::PanelPlace::bottom_left;
  if (position == "bottom-right") return render::PanelPlace::bottom_right;
  if (position == "bottom") return render::PanelPlace::bottom;
  return render::PanelPlace::top_right;
}

}  // namespace

tex::TexTypesetter& film_typesetter() {
  static tex::TexTypesetter typesetter;
  return typesetter;
}

std::string fill_live_values(const std::string& tex, const ImpactNumbers& impact) {
  const std::map<std::string, std::string> values = live_values(impact);
  std::string filled;
  for (size_t i = 0; i < tex.size();) {
    if (tex[i] == '{' && (i == 0 || tex[i - 1] != '\\')) {
      const size_t close = tex.find('}', i);
      if (close != std::string::npos)
        if (const auto value = values.find(tex.substr(i + 1, close - i - 1)); value != values.end()) {
          filled += "{" + value->second + "}";
          i = close + 1;
          continue;
        }
    }
    filled += tex[i++];
  }
  return filled;
}

std::string equation_panel_tex(const std::string& equation, const ImpactNumbers& impact) {
  const double masses = impact.inverse_mass_a + impact.inverse_mass_b;
  const std::string e = figures(impact.restitution);
  const std::string masses_tex = inverse_mass(impact.inverse_mass_a) + " + " + inverse_mass(impact.inverse_mass_b);
  const std::string newton_seconds = "\\ \\mathrm{N\\,s}";
  const std::string solver = "\\text{solver: } " + figures(impact.impulse) + newton_seconds;
  if (equation == "eq13") {
    return "\\begin{aligned}J &= \\frac{-(1+e)\\,v_{ab}\\cdot\\hat n}{1/m_a + 1/m_b + "
           "\\big[(I_a^{-1}(r_a\\times\\hat n))\\times r_a + (I_b^{-1}(r_b\\times\\hat n))\\times r_b\\big]\\cdot\\hat n}\\\\[3pt]"
           "&= \\frac{-(1+" + e + ")\\,(" + figures(impact.point_approach) + ")}{" + masses_tex + " + " +
           figures(impact.angular) + "} = " + figures(eq13_impulse(impact)) + newton_seconds + "\\\\[2pt]" +
           "&\\phantom{=}\\ r_a = " + vector_figures(impact.offset_a) + ",\\ r_b = " + vector_figures(impact.offset_b) +
           "\\ \\mathrm{m};\\quad " + solver + "\\end{aligned}";
  }
  const double correct = masses > 0 ? -(1 + impact.restitution) * impact.approach / masses : 0;
  const double printed = masses > 0 ? -(1 - impact.restitution) * impact.approach / masses : 0;
  const std::string verdict = impact.restitution >= 1  ? "\\text{, none: they pass through}"
                              : impact.restitution > 0 ? "\\text{, too little}"
                                                       : "\\text{, the same at } e = 0";
  return "\\begin{aligned}&J = \\frac{-(1+e)\\,v_{ab}\\cdot\\hat n}{1/m_a + 1/m_b} = \\frac{-(1+" + e + ")\\,(" +
         figures(impact.approach) + ")}{" + masses_tex + "} = " + figures(correct) + newton_seconds + "\\\\[2pt]" +
         "&" + solver + "\\\\&\\text{printed } -(1-e)\\text{: } " +
         figures(printed) + newton_seconds + verdict + "\\end{aligned}";
}

void check_equations(const Scene& scene, tex::TexTypesetter& typesetter) {
  const ImpactNumbers impact = made_up_impact();
  for (const EquationCue& cue : scene.equations) {
    try {
      typesetter.typeset(fill_live_values(cue.tex, impact));
    } catch (const tex::TexError& error) {
      throw SceneError(cue.origin + ": " + error.what());
    }
  }
}

LiveEquations::LiveEquations(const Scene& scene, tex::TexTypesetter& typesetter) : scene_(scene), typesetter_(typesetter) {}

render::OverlayMath LiveEquations::typeset(const std::string& tex, const std::string& origin, float size) const {
  try {
    const std::shared_ptr<const tex::TypesetMath> math = typesetter_.typeset(tex);
    return {math->key, std::shared_ptr<const std::string>(math, &math->svg), tex, size / 12.0f};  // 12 pt TeX
  } catch (const tex::TexError& error) {
    throw SceneError(origin + ": " + error.what());
  }
}

void LiveEquations::prepare(const std::vector<const ImpactNumbers*>& impacts) const {
  std::set<double> seen;  // impacts by time: one a step at most
  for (const ImpactNumbers* impact : impacts) {
    if (impact->time < 0 || !seen.insert(impact->time).second) continue;
    if (scene_.overlay.equation != "none")
      typeset(equation_panel_tex(scene_.overlay.equation, *impact), scene_.path + ": [overlay] equation", kPanelSize);
    for (const EquationCue& cue : scene_.equations)
      if (cue.live) typeset(fill_live_values(cue.tex, *impact), cue.origin, float(cue.size));
  }
  for (const EquationCue& cue : scene_.equations)
    if (!cue.live) typeset(cue.tex, cue.origin, float(cue.size));
}

void LiveEquations::add_panels(double time, const ImpactNumbers& impact, render::Overlay& overlay) const {
  const bool impact_known = impact.time >= 0;
  if (impact_known && scene_.overlay.equation != "none") {
    render::OverlayPanel panel;
    panel.place = render::PanelPlace::top_right;
    panel.colour = mark_colour::normal_impulse;
    char heading[96];
    std::snprintf(heading, sizeof heading, "%s at t = %.2f s (SI units)", scene_.overlay.equation == "eq13" ? "eq. 13" : "eq. 8",
                  impact.time);
    panel.lines = {heading};
    panel.math = typeset(equation_panel_tex(scene_.overlay.equation, impact), scene_.path + ": [overlay] equation",
                         scene_.overlay.equation == "eq13" ? kWidePanelSize : kPanelSize);
    overlay.panels.push_back(std::move(panel));
  }
  for (const EquationCue& cue : scene_.equations) {
    if (time < cue.start || time >= cue.end || (cue.live && !impact_known)) continue;
    render::OverlayPanel panel;
    panel.place = place_named(cue.position);
    panel.math = typeset(cue.live ? fill_live_values(cue.tex, impact) : cue.tex, cue.origin, float(cue.size));
    panel.opacity = cue_opacity(cue.start, cue.end, time);
    overlay.panels.push_back(std::move(panel));
  }
}

}  // namespace impulse::demos
