// An unknown field's message lists the table's fields ("known here: ..."), and the list is the
// parser's own: every field that a catalogue scene's table gives, left out of that table, is still
// named when a typo stands in its place. (A list made of the fields read so far would forget those
// read only when present, as `material` was.)
#include "demos/scene/scene_file.h"

#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace impulse::demos {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTypo = "zz_not_a_field";

// Where a table is in a scene's tables: each step a key, and an index when the key holds a list.
struct Step {
  std::string key;
  int index = -1;  // -1: the key holds a table
};
using TablePath = std::vector<Step>;

toml::table& at(toml::table& root, const TablePath& path) {
  toml::table* table = &root;
  for (const Step& step : path) {
    toml::node* node = table->get(step.key);
    if (step.index >= 0) node = node->as_array()->get(size_t(step.index));
    table = node->as_table();
  }
  return *table;
}

// Every table of `root`, itself first.
void collect(const toml::table& table, TablePath path, std::vector<TablePath>& paths) {
  paths.push_back(path);
  for (const auto& [key, node] : table) {
    path.push_back({std::string(key.str()), -1});
    if (const toml::table* inner = node.as_table()) {
      collect(*inner, path, paths);
    } else if (const toml::array* list = node.as_array(); list && list->is_array_of_tables()) {
      for (size_t i = 0; i < list->size(); ++i) {
        path.back().index = int(i);
        collect(*list->get(i)->as_table(), path, paths);
      }
    }
    path.pop_back();
  }
}

// The fields an unknown-field message names: "... (known here: a, b, c)".
std::vector<std::string> known_fields(const std::string& message) {
  const std::string marker = "(known here: ";
  const size_t begin = message.rfind(marker);
  if (begin == std::string::npos) return {};
  std::stringstream list(message.substr(begin + marker.size(), message.rfind(')') - begin - marker.size()));
  std::vector<std::string> fields;
  for (std::string field; std::getline(list, field, ',');) fields.push_back(field.substr(field.find_first_not_of(' ')));
  return fields;
}

std::vector<std::string> catalogue() {
  std::vector<std::string> paths;
  for (const auto& entry : fs::directory_iterator(fs::path(IMPULSE_SOURCE_DIR) / "assets" / "scenes"))
    if (entry.path().extension() == ".toml") paths.push_back(entry.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

TEST(KnownFields, EveryFieldACatalogueTableGivesIsNamedWhenLeftOut) {
  int named = 0;
  for (const std::string& path : catalogue()) {
    toml::table root = toml::parse_file(path);
    std::vector<TablePath> tables;
    collect(root, {}, tables);
    for (const TablePath& table_path : tables) {
      for (const auto& [key, node] : at(root, table_path)) {
        toml::table changed = root;
        toml::table& table = at(changed, table_path);
        table.erase(key.str());
        table.insert(kTypo, 1);
        std::string message = "no error";
        try {
          SceneFile(std::move(changed), path).scene();
        } catch (const SceneError& error) {
          message = error.what();
        }
        // Without the field the table may fail before its fields are listed (a body without a shape).
        if (message.find("field '" + std::string(kTypo) + "': unknown field") == std::string::npos) {
          EXPECT_NE(message, "no error") << path << ": " << kTypo << " was accepted";
          continue;
        }
        const std::vector<std::string> known = known_fields(message);
        EXPECT_NE(std::find(known.begin(), known.end(), key.str()), known.end())
            << path << ": '" << key.str() << "' is read but not named:\n" << message;
        ++named;
      }
    }
  }
  EXPECT_GT(named, 200);  // the catalogue's tables give hundreds of fields
}

// The newcomer's case: a body without a material, a field misspelt.
TEST(KnownFields, ABodyWithoutAMaterialNamesMaterial) {
  toml::table body{{"shape", "box"}, {"materail", "wood"}};
  toml::table root{{"body", toml::array{body}}};
  try {
    SceneFile(std::move(root), "typo.toml").scene();
    FAIL() << "a misspelt field was accepted";
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("field 'materail': unknown field; did you mean 'material'?"), std::string::npos) << message;
    const std::vector<std::string> known = known_fields(message);
    EXPECT_NE(std::find(known.begin(), known.end(), "material"), known.end()) << message;
    EXPECT_EQ(std::find(known.begin(), known.end(), "radius"), known.end()) << "a box has no radius: " << message;
  }
}

}  // namespace
}  // namespace impulse::demos
