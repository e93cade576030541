#include "demos/response/include_check.h"

#include <cctype>
#include <cstring>
#include <regex>
#include <vector>

namespace impulse::workshop {

namespace {

constexpr const char* kAllowed =
    "graded code may include the standard library's headers by name (#include <cmath>) and impulse/workshop.h, nothing else";

// The text after phase 2: lines joined where a backslash ends one, each character with the line
// it came from.
struct Joined {
  std::string text;
  std::vector<int> line;  // per character, from 1
};

Joined join_lines(const std::string& source) {
  Joined joined;
  int line = 1;
  for (size_t i = 0; i < source.size(); ++i) {
    if (source[i] == '\\' && i + 1 < source.size() && (source[i + 1] == '\n' || (source[i + 1] == '\r' && i + 2 < source.size() && source[i + 2] == '\n'))) {
      i += source[i + 1] == '\r' ? 2 : 1;
      ++line;
      continue;
    }
    joined.text += source[i];
    joined.line.push_back(line);
    if (source[i] == '\n') ++line;
  }
  return joined;
}

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A standard header's name: relative, no "..", plain characters.
bool standard_header(const std::string& name) {
  if (name.empty() || name.front() == '/' || name.find("..") != std::string::npos) return false;
  for (const char c : name)
    if (!identifier_char(c) && c != '.' && c != '/' && c != '+' && c != '-') return false;
  return true;
}

std::string shortened(const std::string& text) { return text.size() > 120 ? text.substr(0, 120) + "..." : text; }

class Scanner {
 public:
  Scanner(const std::string& label, const std::string& source) : label_(label), source_(source), joined_(join_lines(source)) {}

  std::optional<std::string> run() {
    const std::string& t = joined_.text;
    bool line_start = true;
    while (at_ < t.size() && !refusal_) {
      const char c = t[at_];
      if (c == '\n') {
        line_start = true;
        ++at_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++at_;
      } else if (t.compare(at_, 2, "//") == 0 || t.compare(at_, 2, "/*") == 0) {
        skip_comment();
      } else if (line_start && (c == '#' || t.compare(at_, 2, "%:") == 0)) {
        line_start = false;
        directive();
      } else {
        line_start = false;
        token();
      }
    }
    return refusal_;
  }

 private:
  void refuse(size_t where, const std::string& why) {
    refusal_ = label_ + ":" + std::to_string(joined_.line[std::min(where, joined_.line.size() - 1)]) + ": " + why;
  }

  void skip_comment() {
    const std::string& t = joined_.text;
    if (t[at_ + 1] == '/') {
      at_ = std::min(t.find('\n', at_), t.size());
    } else {
      const size_t end = t.find("*/", at_ + 2);
      at_ = end == std::string::npos ? t.size() : end + 2;
    }
  }

  void skip_space_in_line() {
    const std::string& t = joined_.text;
    while (at_ < t.size() && t[at_] != '\n') {
      if (std::isspace(static_cast<unsigned char>(t[at_])))
        ++at_;
      else if (t.compare(at_, 2, "/*") == 0)
        skip_comment();
      else
        break;
    }
  }

  std::string identifier() {
    const size_t start = at_;
    while (at_ < joined_.text.size() && identifier_char(joined_.text[at_])) ++at_;
    return joined_.text.substr(start, at_ - start);
  }

  // A string or character literal from its opening quote; a raw string from R" (its prefix read).
  void literal(bool raw) {
    const std::string& t = joined_.text;
    const char quote = t[at_];
    if (raw) {
      const size_t open = t.find('(', at_);
      if (open == std::string::npos) {
        at_ = t.size();
        return;
      }
      std::string close(1, ')');  // )delimiter"
      close.append(t, at_ + 1, open - at_ - 1);
      close += '"';
      const size_t end = t.find(close, open);
      at_ = end == std::string::npos ? t.size() : end + close.size();
      return;
    }
    for (++at_; at_ < t.size() && t[at_] != quote && t[at_] != '\n'; ++at_)
      if (t[at_] == '\\') ++at_;
    ++at_;
  }

  void token() {
    const std::string& t = joined_.text;
    const char c = t[at_];
    if (c == '"' || c == '\'') return literal(false);
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && at_ + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[at_ + 1])))) {
      // A pp-number, with digit separators (1'000) and exponents' signs.
      for (++at_; at_ < t.size(); ++at_) {
        const char n = t[at_];
        const bool sign = (n == '+' || n == '-') && std::strchr("eEpP", t[at_ - 1]) != nullptr;
        const bool separator = n == '\'' && at_ + 1 < t.size() && identifier_char(t[at_ + 1]);
        if (!identifier_char(n) && n != '.' && !sign && !separator) break;
      }
      return;
    }
    if (!identifier_char(c)) {
      ++at_;
      return;
    }
    const size_t start = at_;
    const std::string word = identifier();
    if (at_ < t.size() && t[at_] == '"' && (word == "R" || word == "u8R" || word == "uR" || word == "UR" || word == "LR"))
      return literal(true);
    if (word == "asm" || word == "__asm" || word == "__asm__")
      refuse(start, word + " is refused: graded code may not contain assembly");
    else if (word == "__has_include" || word == "__has_include_next")
      refuse(start, word + " is refused: graded code may not ask which files exist");
    else if (word == "_Pragma")
      refuse(start, "_Pragma is refused: write a #pragma on a line of its own");
  }

  void directive() {
    const std::string& t = joined_.text;
    const size_t hash = at_;
    at_ += t[at_] == '#' ? 1 : 2;
    skip_space_in_line();
    if (at_ < t.size() && std::isdigit(static_cast<unsigned char>(t[at_])))
      return refuse(hash, "a line marker (# NUMBER \"FILE\") is refused: graded code may not rename its file or renumber its lines");
    const std::string name = identifier();
    if (name == "line") return refuse(hash, "#line is refused: graded code may not rename its file or renumber its lines");
    if (name == "include_next" || name == "import" || name == "embed") return refuse(hash, "#" + name + " is refused: " + kAllowed);
    if (name == "pragma") {
      const size_t end = std::min(t.find('\n', at_), t.size());
      if (t.substr(at_, end - at_).find("dependency") != std::string::npos)
        refuse(hash, "#pragma GCC dependency is refused: graded code may not name other files");
      return;
    }
    if (name == "include") include(hash);
  }

  void include(size_t hash) {
    const std::string& t = joined_.text;
    skip_space_in_line();
    const char open = at_ < t.size() ? t[at_] : '\n';
    const char close = open == '<' ? '>' : '"';
    const size_t end = open == '<' || open == '"' ? t.find(close, at_ + 1) : std::string::npos;
    const size_t line_end = std::min(t.find('\n', at_), t.size());
    if (end == std::string::npos || end > line_end)
      return refuse(hash, "#include " + shortened(t.substr(at_, line_end - at_)) +
                              " is refused: name the header itself (#include <cmath>); " + kAllowed);
    const std::string name = t.substr(at_ + 1, end - at_ - 1), written = t.substr(at_, end + 1 - at_);
    const bool allowed = open == '<' ? standard_header(name) : name == "impulse/workshop.h" || name == "impulse/workshop_abi.h";
    if (!allowed) return refuse(hash, "#include " + shortened(written) + " is refused: " + kAllowed);
    at_ = end + 1;
    // As the wrapper moves it: alone on one line of the file, written with '#'.
    const int line = joined_.line[hash];
    size_t begin = 0;
    for (int n = 1; n < line; ++n) begin = source_.find('\n', begin) + 1;
    std::string physical = source_.substr(begin, source_.find('\n', begin) - begin);
    if (!physical.empty() && physical.back() == '\r') physical.pop_back();
    if (!is_hoisted_include(physical))
      refuse(hash, "#include " + shortened(written) + " is refused as written: put it on a line of its own, as #include <cmath>");
  }

  const std::string& label_;
  const std::string& source_;
  Joined joined_;
  size_t at_ = 0;
  std::optional<std::string> refusal_;
};

}  // namespace

bool is_hoisted_include(const std::string& line) {
  static const std::regex hoisted(R"(^\s*#\s*include\s*(<[^>]*>|"impulse/workshop(_abi)?\.h")\s*(//.*)?$)");
  return std::regex_match(line, hoisted);
}

std::optional<std::string> refused_in_source(const std::string& label, const std::string& text) {
  return Scanner(label, text).run();
}

}  // namespace impulse::workshop
