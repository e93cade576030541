#include "demos/scene/scene_overrides.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string_view>

#include "demos/scene/scene_error.h"

namespace impulse::demos {
namespace {

// The tables a scene file may have, and which of them are lists of tables.
const std::vector<std::string> kTables = {"scene", "world", "camera", "video", "draw", "overlay", "playback", "compare"};
const std::vector<std::string> kLists = {"body", "joint", "caption", "equation", "pyramid", "lattice", "check"};

// The argument as a message shows it: a line break or tab written as \n or \t, so the message
// stays one line.
std::string shown(const std::string& argument) {
  std::string text;
  for (char c : argument) text += c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t" : std::string(1, c);
  return text;
}

[[noreturn]] void refuse(const std::string& argument, const std::string& reason) {
  ScenePlace place;
  place.setting = argument;
  throw SceneError("--set " + shown(argument) + ": " + reason, place);
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Whether `text` begins as a TOML value does (a number, a list, a table, a quoted string, true,
// false, inf, nan): then it must be exactly one, never a bare word.
bool looks_like_toml(const std::string& text) {
  if (text.empty()) return false;
  if (std::string_view("0123456789+-.[{\"'").find(text[0]) != std::string_view::npos) return true;
  for (const std::string_view word : {"true", "false", "inf", "nan"})
    if (text.starts_with(word) && (text.size() == word.size() || !std::isalnum(static_cast<unsigned char>(text[word.size()]))))
      return true;
  return false;
}

// The value as a TOML node, parsed as a scene file's value is. It is exactly one value: anything
// after it (a line break and a second assignment, trailing words) is refused, never dropped.
toml::node_view<toml::node> parse_value(toml::table& holder, const std::string& argument, const std::string& text) {
  if (const size_t end = text.find_first_of("\r\n"); end != std::string::npos)
    refuse(argument, "a value is one line, and a line break follows '" + shown(text.substr(0, end)) +
                         "'; give each field its own --set");
  const std::string source = "--set " + argument;
  try {
    holder = toml::parse("value = " + text, source);
  } catch (const toml::parse_error& error) {
    if (looks_like_toml(text))
      refuse(argument, "cannot read the value '" + text + "': " + std::string(error.description()) +
                           " (write one value, like 0.2, false, [0, 1, 0] or \"text\")");
    std::string quoted = "\"";
    for (char c : text) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    try {
      holder = toml::parse("value = " + quoted + "\"", source);  // a bare word: a string
    } catch (const toml::parse_error& bare_error) {
      refuse(argument, std::string("cannot read the value: ") + std::string(bare_error.description()));
    }
  }
  if (holder.size() != 1) refuse(argument, "more than one value; give each field its own --set");
  return holder["value"];
}

// "body[ball]" -> name "body", selector "ball"; "world" -> "world", no selector.
struct Segment {
  std::string name;
  std::string selector;
  bool selected = false;
};
Segment parse_segment(const std::string& argument, const std::string& text) {
  Segment segment;
  const size_t open = text.find('[');
  segment.name = text.substr(0, open);
  if (open != std::string::npos) {
    if (text.back() != ']' || text.size() < open + 3) refuse(argument, "'" + text + "' must be NAME[INDEX] or NAME[NAME]");
    segment.selector = text.substr(open + 1, text.size() - open - 2);
    segment.selected = true;
  }
  if (segment.name.empty()) refuse(argument, "an empty name in the path");
  return segment;
}

// The table of `list` chosen by an index from 0 or by its `name` field.
toml::table& select(const std::string& argument, const std::string& list_name, toml::array& list,
                    const std::string& selector) {
  const bool digits = !selector.empty() && std::all_of(selector.begin(), selector.end(), ::isdigit);
  if (digits) {
    // More digits than any list has tables would overflow the conversion: out of range too.
    const size_t index = selector.size() > 9 ? list.size() : std::stoul(selector);
    if (index >= list.size())
      refuse(argument, "there " + std::string(list.size() == 1 ? "is 1 " : "are " + std::to_string(list.size()) + " ") +
                           "[[" + list_name + "]] table" + (list.size() == 1 ? "" : "s") + ", numbered from 0");
    return *list.get(index)->as_table();
  }
  std::vector<std::string> names;
  for (toml::node& item : list) {
    toml::table& table = *item.as_table();
    const auto name = table["name"].value<std::string>();
    if (name && *name == selector) return table;
    if (name) names.push_back(*name);
  }
  std::string known;
  for (const std::string& name : names) known += (known.empty() ? "'" : ", '") + name + "'";
  const std::string hint = did_you_mean(selector, names);
  refuse(argument, "no [[" + list_name + "]] is named '" + selector + "'" + (hint.empty() ? "" : "; " + hint) +
                       (known.empty() ? "" : " (named: " + known + ")"));
}

void apply_override(toml::table& root, const std::string& argument, WrittenNodes& written) {
  const size_t equals = argument.find('=');
  if (equals == std::string::npos || equals == 0)
    refuse(argument, "expected KEY=VALUE, like world.friction=false or body[ball].restitution=0.2");
  const std::string key = argument.substr(0, equals);

  std::vector<std::string> parts;
  std::stringstream stream(key);
  for (std::string part; std::getline(stream, part, '.');) parts.push_back(part);
  if (parts.size() < 2) refuse(argument, "KEY names a field of a table, like world." + key);

  toml::table* table = &root;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    const Segment segment = parse_segment(argument, parts[i]);
    const bool top = table == &root;
    const bool list = top ? std::count(kLists.begin(), kLists.end(), segment.name) > 0
                          : table->get(segment.name) && table->get(segment.name)->is_array_of_tables();
    if (top && !list && !std::count(kTables.begin(), kTables.end(), segment.name)) {
      std::vector<std::string> known = kTables;
      known.insert(known.end(), kLists.begin(), kLists.end());
      const std::string hint = did_you_mean(segment.name, known);
      refuse(argument, "a scene has no table '" + segment.name + "'" + (hint.empty() ? "" : "; " + hint));
    }
    if (list) {
      toml::array* tables = (*table)[segment.name].as_array();
      if (!segment.selected) refuse(argument, "[[" + segment.name + "]] is a list: choose one, like " + segment.name + "[0]");
      if (!tables || tables->empty()) refuse(argument, "the scene has no [[" + segment.name + "]] table");
      table = &select(argument, segment.name, *tables, segment.selector);
      continue;
    }
    if (segment.selected) refuse(argument, "'" + segment.name + "' is a table, not a list: no [" + segment.selector + "]");
    if (!table->get(segment.name)) table->insert(segment.name, toml::table{});
    table = (*table)[segment.name].as_table();
    if (!table) refuse(argument, "'" + segment.name + "' is not a table");
  }
  const Segment field = parse_segment(argument, parts.back());
  if (field.selected) refuse(argument, "the last part of KEY is a field's name, without [ ]");
  toml::table holder;
  const toml::node_view<toml::node> value = parse_value(holder, argument, argument.substr(equals + 1));
  table->insert_or_assign(field.name, *value.node());
  written[table->get(field.name)] = "--set " + argument;
}

}  // namespace

WrittenNodes apply_overrides(toml::table& root, const std::vector<std::string>& settings) {
  WrittenNodes written;
  for (const std::string& argument : settings) apply_override(root, argument, written);
  return written;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& known) {
  std::string best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const std::string& candidate : known) {
    const size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best.empty() ? "" : "did you mean '" + best + "'?";
}

}  // namespace impulse::demos
