#include "tex/tex_typesetter.h"

#include "tex/child_run.h"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace impulse::tex {
namespace {

constexpr const char* kMathOpening = "$\\displaystyle ";
constexpr const char* kInstall =
    "install TeX with `apt-get install texlive-latex-base dvisvgm` (scripts/setup.sh does)";

std::string read_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// A directory of its own under the system's temporary directory, removed with all in it.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "impulse-tex-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw TexError("LaTeX: cannot make a temporary directory in " + pattern);
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// A '$' not written \$ would end the mathematics and let text mode in.
void refuse_dollar(const std::string& math) {
  for (size_t i = 0; i < math.size(); ++i)
    if (math[i] == '$' && (i == 0 || math[i - 1] != '\\'))
      throw TexError("LaTeX: a '$' in the expression, which is mathematics already (write \\$ for a dollar sign)");
}

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace

std::string latex_error(const std::string& log) {
  std::istringstream lines(log);
  std::string line, message;
  while (std::getline(lines, line))
    if (line.rfind("! ", 0) == 0) {
      message = trim(line.substr(2));
      break;
    }
  if (message.empty()) return "latex failed (no error in its log)";
  if (!message.empty() && message.back() == '.') message.pop_back();
  // The line where TeX stopped reads "l.6 <what it read so far>": for an undefined control
  // sequence its last word is the culprit; otherwise it shows where.
  std::string context;
  while (std::getline(lines, line))
    if (line.rfind("l.", 0) == 0 && line.find(' ') != std::string::npos) {
      context = line.substr(line.find(' ') + 1);
      break;
    }
  // Without the document's own words around the expression.
  if (context.rfind(kMathOpening, 0) == 0) context = context.substr(std::string(kMathOpening).size());
  if (!context.empty() && context.back() == '$') context.pop_back();
  if (message == "Undefined control sequence") {
    const size_t slash = context.rfind('\\');
    if (slash != std::string::npos) return message + " " + trim(context.substr(slash));
  }
  context = trim(context);
  return context.empty() ? message : message + " after '" + context + "'";
}

TexTypesetter::TexTypesetter(TexCache cache, double seconds_allowed)
    : cache_(std::move(cache)), seconds_allowed_(seconds_allowed) {}

std::string TexTypesetter::document(const std::string& math) {
  return "\\documentclass[12pt]{article}\n"
         "\\usepackage{amsmath}\n"
         "\\usepackage{amssymb}\n"
         "\\pagestyle{empty}\n"
         "\\begin{document}\n" +
         std::string(kMathOpening) + math + "$\n\\end{document}\n";
}

std::shared_ptr<const TypesetMath> TexTypesetter::typeset(const std::string& math) {
  refuse_dollar(math);
  const std::string source = document(math);
  const std::string key = text_hash(source);
  {
    const std::lock_guard lock(mutex_);
    if (const auto found = typeset_.find(key); found != typeset_.end()) return found->second;
  }
  auto result = std::make_shared<TypesetMath>();
  result->key = key;
  if (std::optional<std::string> cached = cache_.read(key)) {
    result->svg = std::move(*cached);
  } else {
    result->svg = run_latex(source);
    cache_.write(key, result->svg);
  }
  const std::lock_guard lock(mutex_);
  return typeset_.emplace(key, std::move(result)).first->second;
}

std::string TexTypesetter::run_latex(const std::string& source) {
  const TemporaryDirectory directory;
  const std::filesystem::path dir = directory.path();
  {
    std::ofstream file(dir / "math.tex", std::ios::binary);
    file << source;
    if (!file) throw TexError("LaTeX: cannot write " + (dir / "math.tex").string());
  }
  ++latex_runs_;
  const ChildOutcome latex =
      run_child({"latex", "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error", "math.tex"}, dir.string(),
                (dir / "latex.out").string(), seconds_allowed_);
  if (!latex.started) throw TexError("LaTeX: cannot run latex (" + latex.error + "): " + kInstall);
  if (latex.timed_out)
    throw TexError("LaTeX: latex took longer than " + std::to_string(int(seconds_allowed_)) + " s and was stopped (an endless loop?)");
  if (latex.exit_code != 0 || !std::filesystem::exists(dir / "math.dvi")) {
    const std::string log = read_file(dir / "math.log");
    if (log.find("! LaTeX Error: File `") != std::string::npos)
      throw TexError("LaTeX: " + latex_error(log) + ": " + kInstall);
    throw TexError("LaTeX: " + latex_error(log));
  }
  const ChildOutcome dvisvgm = run_child({"dvisvgm", "--no-fonts", "--exact-bbox", "-o", "math.svg", "math.dvi"},
                                         dir.string(), (dir / "dvisvgm.out").string(), seconds_allowed_);
  if (!dvisvgm.started) throw TexError("LaTeX: cannot run dvisvgm (" + dvisvgm.error + "): " + kInstall);
  std::string svg = read_file(dir / "math.svg");
  if (dvisvgm.timed_out || dvisvgm.exit_code != 0 || svg.find("</svg>") == std::string::npos)
    throw TexError("LaTeX: dvisvgm could not make an SVG: " + trim(read_file(dir / "dvisvgm.out")));
  return svg;
}

}  // namespace impulse::tex
