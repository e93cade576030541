#include "demos/scene/table_reader.h"

#include <fstream>

#include "demos/scene/scene_error.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace impulse::demos {

void NodeOrigins::pair(const toml::node& copy, const toml::node& original) {
  parsed[&copy] = &original;
  if (const toml::table* table = copy.as_table()) {
    const toml::table* from = original.as_table();
    if (!from) return;
    for (const auto& [key, node] : *table)
      if (const toml::node* match = from->get(key.str())) pair(node, *match);
  } else if (const toml::array* array = copy.as_array()) {
    const toml::array* from = original.as_array();
    if (!from) return;
    for (size_t i = 0; i < std::min(array->size(), from->size()); ++i) pair(*array->get(i), *from->get(i));
  }
}

TableReader::TableReader(const toml::table& table, std::string file, const NodeOrigins* origins, std::string where)
    : table_(table), file_(std::move(file)), origins_(origins), where_(std::move(where)) {}

void TableReader::fail(const toml::node* node, std::string_view key, const std::string& reason) const {
  throw SceneError(where(node, key) + ": " + reason, place(node, key));
}

// The node shown for `node` (the table's when null): the parsed one, which has the line.
const toml::node& TableReader::shown(const toml::node* node) const {
  const toml::node* shown = node ? node : &table_;
  if (origins_)
    if (const auto found = origins_->parsed.find(shown); found != origins_->parsed.end()) shown = found->second;
  return *shown;
}

// The --set argument that wrote `node`, or null.
const std::string* TableReader::set_by(const toml::node* node) const {
  if (!origins_ || !node) return nullptr;
  const auto found = origins_->arguments.find(node);
  return found != origins_->arguments.end() ? &found->second : nullptr;
}

ScenePlace TableReader::place(const toml::node* node, std::string_view key) const {
  ScenePlace place{file_, int(shown(node).source().begin.line), where_, std::string(key), ""};
  if (const std::string* argument = set_by(node)) {
    place.setting = argument->substr(argument->rfind("--set ", 0) == 0 ? 6 : 0);
    place.line = 0;
  }
  return place;
}

char TableReader::quotes(const toml::node* node) const {
  if (!node || set_by(node)) return 0;
  const toml::source_position begin = shown(node).source().begin;
  if (begin.line == 0 || begin.column == 0) return 0;
  std::ifstream in(file_);
  std::string line;
  for (toml::source_index i = 0; i < begin.line; ++i)
    if (!std::getline(in, line)) return 0;
  const size_t at = begin.column - 1;
  if (at >= line.size()) return 0;
  if (line[at] == '\'') return '\'';
  if (line[at] != '"') return 0;
  return line.compare(at, 3, "\"\"\"") == 0 ? 'B' : '"';
}

std::string TableReader::where(const toml::node* node, std::string_view key) const {
  std::ostringstream message;
  // A value given on the command line is named by its --set argument, not by a line of the file;
  // tables built in memory (Python's dicts) have no lines.
  if (const std::string* argument = set_by(node))
    message << *argument << ": " << where_;
  else if (const int line = int(shown(node).source().begin.line); line > 0)
    message << file_ << ':' << line << ": " << where_;
  else
    message << file_ << ": " << where_;
  if (!key.empty()) message << " field '" << key << "'";
  return message.str();
}

const toml::node* TableReader::get(std::string_view key) {
  used_.insert(std::string(key));
  return table_.get(key);
}

bool TableReader::has(std::string_view key) { return get(key) != nullptr; }

double TableReader::number(std::string_view key, double fallback, double min, double max, bool exclusive_min) {
  const toml::node* node = get(key);
  if (!node) return fallback;
  double value = 0;
  if (auto v = node->value_exact<double>()) value = *v;
  else if (auto i = node->value_exact<int64_t>()) value = double(*i);
  else fail(node, key, "must be a number");
  if (!std::isfinite(value)) fail(node, key, "must be finite");
  const bool too_small = exclusive_min ? value <= min : value < min;
  if (too_small || value > max) {
    std::ostringstream range;
    range << "must be " << (exclusive_min ? "> " : ">= ") << min;
    if (std::isfinite(max)) range << " and <= " << max;
    range << ", got " << value;
    fail(node, key, range.str());
  }
  return value;
}

int TableReader::integer(std::string_view key, int fallback, int min, int max) {
  const toml::node* node = get(key);
  if (!node) return fallback;
  auto v = node->value_exact<int64_t>();
  if (!v) fail(node, key, "must be a whole number");
  if (*v < min || *v > max)
    fail(node, key, "must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " + std::to_string(*v));
  return int(*v);
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* node = get(key);
  if (!node) return fallback;
  auto v = node->value_exact<bool>();
  if (!v) fail(node, key, "must be true or false");
  return *v;
}

std::string TableReader::string(std::string_view key, std::string fallback) {
  const toml::node* node = get(key);
  if (!node) return fallback;
  auto v = node->value_exact<std::string>();
  if (!v) fail(node, key, "must be a string in quotes");
  return *v;
}

std::string TableReader::choice(std::string_view key, std::string fallback, std::span<const std::string_view> choices) {
  const std::string value = string(key, fallback);
  std::string known;
  for (std::string_view c : choices) {
    if (c == value) return value;
    known += (known.empty() ? "" : ", ") + std::string(c);
  }
  const toml::node* node = get(key);
  const std::string hint = did_you_mean(value, std::vector<std::string>(choices.begin(), choices.end()));
  fail(node, key,
       node ? "unknown value '" + value + "'" + (hint.empty() ? "" : "; " + hint) + " (known: " + known + ")"
            : "missing (one of: " + known + ")");
}

physics::Vec3 TableReader::vec3(std::string_view key, const physics::Vec3& fallback) {
  const toml::node* node = get(key);
  if (!node) return fallback;
  const toml::array* array = node->as_array();
  const char* expected = "must be an array of three numbers, like [0, 1, 0]";
  if (!array || array->size() != 3) fail(node, key, expected);
  physics::Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const toml::node& item = *array->get(i);
    if (auto d = item.value_exact<double>()) v[i] = *d;
    else if (auto n = item.value_exact<int64_t>()) v[i] = physics::Real(*n);
    else fail(node, key, expected);
    if (!std::isfinite(v[i])) fail(node, key, "must be finite");
  }
  return v;
}

physics::Vec3 TableReader::vec3(std::string_view key, const physics::Vec3& fallback, double max_length,
                                const char* unit, const char* why) {
  const physics::Vec3 v = vec3(key, fallback);
  if (v.norm() > max_length) {
    std::ostringstream reason;
    reason << "must be at most " << max_length << " " << unit << " long, got " << v.norm() << ": " << why;
    fail(get(key), key, reason.str());
  }
  return v;
}

std::vector<physics::Vec3> TableReader::points(std::string_view key, double max_length, size_t most) {
  const toml::node* node = get(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  const char* expected = "must be a list of points, each three numbers: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]";
  if (!array) fail(node, key, expected);
  if (array->size() > most) fail(node, key, "has " + std::to_string(array->size()) + " points; at most " + std::to_string(most));
  std::vector<physics::Vec3> out;
  for (size_t i = 0; i < array->size(); ++i) {
    const toml::array* point = array->get(i)->as_array();
    const std::string which = "point " + std::to_string(i + 1) + " must be three numbers [x, y, z] in metres";
    if (!point || point->size() != 3) fail(array->get(i), key, which);
    physics::Vec3 v;
    for (int k = 0; k < 3; ++k) {
      const toml::node& item = *point->get(k);
      if (auto d = item.value_exact<double>()) v[k] = *d;
      else if (auto n = item.value_exact<int64_t>()) v[k] = physics::Real(*n);
      else fail(array->get(i), key, which);
    }
    if (!physics::is_finite(v) || v.norm() > max_length)
      fail(array->get(i), key, "point " + std::to_string(i + 1) + " must be finite and at most " + std::to_string(int(max_length)) + " m from the body's origin");
    out.push_back(v);
  }
  return out;
}

Colour TableReader::colour(std::string_view key, Colour fallback) {
  const toml::node* node = get(key);
  if (!node) return fallback;
  auto text = node->value_exact<std::string>();
  unsigned rgb = 0;
  if (!text || text->size() != 7 || (*text)[0] != '#' || std::sscanf(text->c_str() + 1, "%6x", &rgb) != 1)
    fail(node, key, "must be a colour like \"#e69f00\"");
  return {float((rgb >> 16) & 255) / 255, float((rgb >> 8) & 255) / 255, float(rgb & 255) / 255};
}

const toml::table* TableReader::table(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return nullptr;
  if (!node->is_table()) fail(node, key, "must be a table, like [" + std::string(key) + "]");
  return node->as_table();
}

const toml::array* TableReader::table_list(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return nullptr;
  const toml::array* list = node->as_array();
  if (!list || !list->is_array_of_tables()) fail(node, key, "must be a list of [[" + std::string(key) + "]] tables");
  return list;
}

void TableReader::finish() const {
  for (const auto& [key, node] : table_) {
    if (used_.count(key.str())) continue;
    std::string known;
    for (const auto& k : used_) known += (known.empty() ? "" : ", ") + k;
    const std::string hint = did_you_mean(std::string(key.str()), std::vector<std::string>(used_.begin(), used_.end()));
    fail(&node, key.str(), "unknown field" + (hint.empty() ? std::string() : "; " + hint) + " (known here: " + known + ")");
  }
}

}  // namespace impulse::demos
