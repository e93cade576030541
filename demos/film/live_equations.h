// The typeset mathematics of a film: each [[equation]] of the scene and the [overlay] equation
// panel (eq. 8 or eq. 13), with the latest impact's numbers filled in, set by LaTeX
// (tex/tex_typesetter.h). Every text the frames will show is typeset by prepare(), before the
// first frame is drawn, so the overlay's painting never waits on latex.
//
// The scene loader runs no program (it stays quick for the bad-scene tests and the fuzzer), so
// the TeX of a scene is checked here, by check_equations(), which `check` and every render call.
#pragma once
#include "demos/film/impact_numbers.h"
#include "demos/scene/scene.h"
#include "render/overlay.h"
#include "tex/tex_typesetter.h"

#include <string>
#include <vector>

namespace impulse::demos {

// The process's typesetter: one in-memory memo over the on-disk cache for every film.
tex::TexTypesetter& film_typesetter();

// `tex` with each live value ({e}, {J}, ...: equation_cue.h) replaced by the impact's number,
// three significant figures as labels write them, kept in braces ("{e}" -> "{0.70}").
std::string fill_live_values(const std::string& tex, const ImpactNumbers& impact);

// The [overlay] equation panel's mathematics ("eq8" or "eq13") with the impact's numbers.
std::string equation_panel_tex(const std::string& equation, const ImpactNumbers& impact);

// Typesets each [[equation]] (live values filled with made-up numbers). Throws SceneError
// "FILE:LINE: [[equation]] N field 'tex': LaTeX: ..." for TeX that latex refuses, or no latex.
void check_equations(const Scene& scene, tex::TexTypesetter& typesetter = film_typesetter());

class LiveEquations {
 public:
  LiveEquations(const Scene& scene, tex::TexTypesetter& typesetter);

  // Typesets every text shown with these impacts (the frames' latest, in any order, repeats
  // allowed); throws SceneError as check_equations does.
  void prepare(const std::vector<const ImpactNumbers*>& impacts) const;
  // The panels shown at simulated `time` after `impact` (time < 0: none yet), placed by name.
  void add_panels(double time, const ImpactNumbers& impact, render::Overlay& overlay) const;

 private:
  render::OverlayMath typeset(const std::string& tex, const std::string& origin, float size) const;

  const Scene& scene_;
  tex::TexTypesetter& typesetter_;
};

}  // namespace impulse::demos
