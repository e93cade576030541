// Reads one TOML table of a scene file, checking each field's type and range. finish() refuses
// any key it was never asked for, so a typo is never silently ignored.
#pragma once
#include "physics/math.h"
#include "demos/scene/view_options.h"

#include <toml++/toml.h>

#include <cmath>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>

namespace impulse::demos {

// While a scene is read, the values --set wrote: a message about one names its argument instead
// of a line of the file. One scope at a time per thread.
class OverrideScope {
 public:
  explicit OverrideScope(const std::map<const toml::node*, std::string>& written);
  ~OverrideScope();
  OverrideScope(const OverrideScope&) = delete;
  OverrideScope& operator=(const OverrideScope&) = delete;
};

class TableReader {
 public:
  // `where` names the table in messages, e.g. "[camera]" or "[[body]] 'ball'".
  TableReader(const toml::table& table, std::string file, std::string where);

  // Throws SceneError "FILE:LINE: WHERE field 'KEY': REASON" (the node's line, else the table's).
  [[noreturn]] void fail(const toml::node* node, std::string_view key, const std::string& reason) const;
  // What fail() writes before ": REASON", for a message made later (e.g. about a field's LaTeX).
  std::string where(const toml::node* node, std::string_view key) const;

  const toml::node* get(std::string_view key);  // marks the key as known; null when absent
  bool has(std::string_view key) const { return table_.contains(key); }  // without marking it
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
  Colour colour(std::string_view key, Colour fallback);

  // The sub-table `key` of this table, or null when absent; anything but a table is an error.
  const toml::table* table(std::string_view key);
  // The list of [[key]] tables, or null when absent; anything else is an error.
  const toml::array* table_list(std::string_view key);

  void finish() const;  // call last

 private:
  const toml::table& table_;
  std::string file_;
  std::string where_;
  std::set<std::string, std::less<>> used_;
};

}  // namespace impulse::demos
