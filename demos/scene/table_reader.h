// Reads one TOML table of a scene file, checking each field's type and range. finish() refuses
// any key it was never asked for, so a typo is never silently ignored.
#pragma once
#include "demos/scene/scene_error.h"
#include "demos/scene/scene_overrides.h"
#include "demos/scene/view_options.h"
#include "physics/math.h"

#include <toml++/toml.h>

#include <cmath>
#include <map>
#include <unordered_map>
#include <set>
#include <span>
#include <string>
#include <string_view>

namespace impulse::demos {

// Where each value of the tables a scene is read from came from, for its messages. The tables are
// a copy of the file's parse with the --set arguments written over it (scene_file.h), and a copy
// has no lines (toml++ copies no source regions): each copied node is paired with the parsed one.
struct NodeOrigins {
  WrittenNodes arguments;  // written by --set: named by the argument
  std::unordered_map<const toml::node*, const toml::node*> parsed;  // a copied node -> the parsed node, with its line

  // Pairs each node of `copy` with the node at the same place in `parsed` (`copy` is `parsed`
  // copied, then written over: where the two differ, nothing is paired).
  void pair(const toml::node& copy, const toml::node& original);
};

class TableReader {
 public:
  // `where` names the table in messages, e.g. "[camera]" or "[[body]] 'ball'"; a value that
  // `origins` holds is named by its --set argument instead of a line of `file`. `origins` (may be
  // null) must outlive the reader.
  TableReader(const toml::table& table, std::string file, const NodeOrigins* origins, std::string where);
  // A reader of a table inside this one: the same file and origins.
  TableReader child(const toml::table& table, std::string where) const { return {table, file_, origins_, std::move(where)}; }

  // Throws SceneError "FILE:LINE: WHERE field 'KEY': REASON" (the node's line, else the table's).
  [[noreturn]] void fail(const toml::node* node, std::string_view key, const std::string& reason) const;
  // What fail() writes before ": REASON", for a message made later (e.g. about a field's LaTeX).
  std::string where(const toml::node* node, std::string_view key) const;
  // The same in parts (scene_error.h).
  ScenePlace place(const toml::node* node, std::string_view key) const;
  // How the file quoted the string `node`: '"' (basic, one line), 'B' (basic, multi-line), '\''
  // (literal, one or more lines), or 0 when it has no line of the file (--set, a dict).
  char quotes(const toml::node* node) const;

  // The fields finish() names as known are those asked for, by get(), has() or a typed read, so
  // ask about every field the table can have (in its kind: a sphere's, a rod's) before finish().
  const toml::node* get(std::string_view key);  // marks the key as known; null when absent
  bool has(std::string_view key);               // marks the key as known
  // Whether the table gives `key` without marking it: for a field the caller refuses here (another
  // kind's), which finish() must not name as known.
  bool gives(std::string_view key) const { return table_.contains(key); }
  double number(std::string_view key, double fallback, double min = -INFINITY, double max = INFINITY,
                bool exclusive_min = false);
  int integer(std::string_view key, int fallback, int min, int max);
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, std::string fallback);
  // One of `choices`, e.g. method = "impulse".
  std::string choice(std::string_view key, std::string fallback, std::span<const std::string_view> choices);
  std::string choice(std::string_view key, std::string fallback, std::initializer_list<std::string_view> choices) {
    return choice(key, std::move(fallback), std::span<const std::string_view>(choices.begin(), choices.size()));
  }
  physics::Vec3 vec3(std::string_view key, const physics::Vec3& fallback);
  // The same, refused when longer than `max_length` (in `unit`), saying `why`.
  physics::Vec3 vec3(std::string_view key, const physics::Vec3& fallback, double max_length, const char* unit,
                     const char* why);
  // A list of points [[x, y, z], ...], each at most `max_length` from the origin; empty when absent.
  std::vector<physics::Vec3> points(std::string_view key, double max_length, size_t most);
  Colour colour(std::string_view key, Colour fallback);

  // The sub-table `key` of this table, or null when absent; anything but a table is an error.
  const toml::table* table(std::string_view key);
  // The list of [[key]] tables, or null when absent; anything else is an error.
  const toml::array* table_list(std::string_view key);

  void finish() const;  // call last

 private:
  const toml::node& shown(const toml::node* node) const;
  const std::string* set_by(const toml::node* node) const;

  const toml::table& table_;
  std::string file_;
  const NodeOrigins* origins_;
  std::string where_;
  std::set<std::string, std::less<>> used_;
};

}  // namespace impulse::demos
