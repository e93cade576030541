#include "demos/scene/toml_syntax.h"

#include <algorithm>

namespace impulse::demos {
namespace {

// Line `number` (from 1) of `text`, without its line break; empty past the end.
std::string_view line_of(std::string_view text, int number) {
  size_t begin = 0;
  for (int n = 1; n < number; ++n) {
    begin = text.find('\n', begin);
    if (begin == std::string_view::npos) return {};
    ++begin;
  }
  std::string_view line = text.substr(begin, text.find('\n', begin) - begin);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

// " (the line: shape = "sphere)": the line as written, trimmed, at most 60 characters.
std::string quoted(std::string_view line) {
  const size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  line = line.substr(first, line.find_last_not_of(" \t") + 1 - first);
  std::string shown(line.substr(0, 60));
  if (line.size() > 60) shown += "...";
  return " (the line: " + shown + ")";
}

// The line (from 1) of the last `quotes` in `text`, or 0. An unclosed """ string holds no """
// (one would close it), so the last is where it opens.
int line_of_last(std::string_view text, std::string_view quotes) {
  const size_t at = text.rfind(quotes);
  if (at == std::string_view::npos) return 0;
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

// The name in the last '...' of toml++'s detail ("cannot redefine existing table 'world'").
std::string quoted_name(std::string_view detail) {
  const size_t close = detail.rfind('\'');
  const size_t open = close == std::string_view::npos || close == 0 ? std::string_view::npos : detail.rfind('\'', close - 1);
  return open == std::string_view::npos ? std::string() : std::string(detail.substr(open + 1, close - open - 1));
}

bool has(std::string_view text, std::string_view part) { return text.find(part) != std::string_view::npos; }

}  // namespace

std::string plain_syntax_error(std::string_view description, int line, int column, std::string_view text) {
  // toml++ writes "Error while parsing WHAT: DETAIL".
  constexpr std::string_view kPrefix = "Error while parsing ";
  const size_t colon = description.find(": ");
  if (description.rfind(kPrefix, 0) != 0 || colon == std::string_view::npos) return std::string(description);
  const std::string_view what = description.substr(kPrefix.size(), colon - kPrefix.size());
  const std::string_view detail = description.substr(colon + 2);
  const std::string_view written = line_of(text, line);
  const std::string shown = quoted(written);
  const std::string name = quoted_name(detail);

  if (what == "string" || what == "literal string") {
    const bool at_line_end = column > int(written.size());
    if (has(detail, "control characters") && at_line_end)
      return "a string opened on line " + std::to_string(line) +
             " is not closed: end it on that line with the quote it opens with, or use \"\"\" for text over several "
             "lines" + shown;
    if (has(detail, "end-of-file")) {
      const std::string_view quotes = what == "string" ? "\"\"\"" : "'''";
      const int opened = line_of_last(text, quotes);
      return "the file ends inside a string" +
             (opened > 0 ? " opened with " + std::string(quotes) + " on line " + std::to_string(opened) : std::string()) +
             ": close it with " + std::string(quotes);
    }
  }
  if (has(detail, "cannot redefine existing")) {
    if (what != "table header") return "'" + name + "' is given twice in one table: keep one" + shown;
    if (has(detail, "existing array") && has(detail, "as table"))
      return "[" + name + "] after [[" + name + "]] tables: write [[" + name + "]] for one more of the list" + shown;
    if (has(detail, "as table"))
      return "[" + name + "] names a value given above, which cannot also be a table: rename one of them" + shown;
    return "[" + name + "] is given twice: put all its fields under one [" + name +
           "] (only lists of tables, like [[body]], repeat)" + shown;
  }
  if (what == "table header") {
    if (has(detail, "expected ']'"))
      return "the table header is not closed: end it with ] for a table, ]] for one of a list like [[body]]" + shown;
    if (has(detail, "saw ']'"))
      return "the table header has one ] too many: write [name] for a table, [[name]] for one of a list" + shown;
  }
  if (what == "inline table") {
    if (has(detail, "dangling comma"))
      return "a comma before the closing }: an inline table has none after its last field" + shown;
    if (has(detail, "saw '\\n'") || has(detail, "end-of-file"))
      return "an inline table { ... } is not closed on its line: close it with } (an inline table stays on one "
             "line; for more, write a [table])" + shown;
    return "an inline table's fields are separated by commas, like { a = 1, b = 2 }" + shown;
  }
  if (what == "array") {
    if (has(detail, "end-of-file")) return "the file ends inside an array: close it with ], like [0, 1, 0]";
    if (column == 1) {  // toml++ stops at the next line's key: the array opens on a line above
      int opened = std::max(line - 1, 1);
      while (opened > 1 && line_of(text, opened).find('[') == std::string_view::npos) --opened;
      return "an array opened on line " + std::to_string(opened) + " is not closed: end it with ], like [0, 1, 0]" +
             quoted(line_of(text, opened));
    }
    return "an array's values are separated by commas and it ends with ], like [0, 1, 0]" + shown;
  }
  if (what == "key-value pair") {
    if (has(detail, "expected '='")) return "a key without '=': write key = value, like shape = \"sphere\"" + shown;
    if (has(detail, "expected value"))
      return "nothing after the '=': give the value, like radius = 0.5 or shape = \"sphere\"" + shown;
    if (has(detail, "expected a comment or whitespace"))
      return "more after the value: one key = value a line (text in quotes; a comment starts with #)" + shown;
  }
  if (what == "value" && has(detail, "could not determine value type"))
    return "not a value: text goes in quotes, like \"sphere\"; numbers, true, false, [arrays] and { inline tables } "
           "do not" + shown;
  if (what == "boolean") return "write true or false, in small letters" + shown;
  if (what == "root table") return "a line that is neither key = value nor a [table] header" + shown;
  return std::string(description);
}

}  // namespace impulse::demos
