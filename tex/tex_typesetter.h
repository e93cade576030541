// LaTeX mathematics to SVG, as Manim does it: the expression goes into a small LaTeX document
// (article, amsmath, amssymb, display style), `latex` makes a DVI and `dvisvgm --no-fonts` turns
// it into an SVG of paths (no fonts needed to draw it). Each document is typeset once: the SVG is
// kept by the document's hash in a TexCache (tex_cache.h) on disk and in memory.
//
// latex runs as a child process in a temporary directory of its own, with -no-shell-escape,
// -interaction=nonstopmode and -halt-on-error, and a time limit (an endless TeX loop is killed).
// This library needs nothing of the scene, the film or the renderer: the film typesets a scene's
// equations with it before any frame is drawn, and the program checks a scene's TeX with it.
#pragma once
#include "tex/tex_cache.h"

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace impulse::tex {

// TeX that latex refuses, or no latex to run. what() reads "LaTeX: Undefined control sequence
// \fracc" or says what to install.
class TexError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TypesetMath {
  std::string key;  // the document's hash: the same for the same expression
  std::string svg;  // dvisvgm's SVG (sizes in TeX points, paths filled black)
};

class TexTypesetter {
 public:
  explicit TexTypesetter(TexCache cache = TexCache(), double seconds_allowed = 20);

  // The typeset `math` (LaTeX math mode, e.g. "J = \frac{1}{2}"). Throws TexError. Thread-safe.
  std::shared_ptr<const TypesetMath> typeset(const std::string& math);

  // How many times latex has run in this typesetter (a cache hit runs none): for tests.
  int latex_runs() const { return latex_runs_; }
  const TexCache& cache() const { return cache_; }

  // The whole LaTeX document an expression is set in.
  static std::string document(const std::string& math);

 private:
  std::string run_latex(const std::string& document);  // the SVG; throws TexError

  TexCache cache_;
  double seconds_allowed_;
  std::atomic<int> latex_runs_{0};
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const TypesetMath>> typeset_;  // by key
};

// The error latex reports in `log` (its .log file), as one line: "Undefined control sequence
// \fracc", "Missing } inserted" ...
std::string latex_error(const std::string& log);

}  // namespace impulse::tex
