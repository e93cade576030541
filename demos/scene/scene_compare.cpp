#include "demos/scene/scene_compare.h"

#include "demos/scene/scene_sections.h"

#include <sstream>

namespace impulse::demos {

std::string unvariable_reason(const std::string& key) {
  for (const std::string shared : {"video", "playback", "camera", "scene.duration"}) {
    if (key == shared || key.rfind(shared + ".", 0) == 0 || key.rfind(shared + "[", 0) == 0)
      return "every pane of a comparison has the same " + shared +
             "; vary a setting of the world, the bodies or the drawing (or use --set for all panes)";
  }
  return "";
}

CompareSpec compare_from_vary(const std::string& vary) {
  CompareSpec compare;
  compare.origin = "--vary " + vary;
  const size_t equals = vary.find('=');
  compare.key = vary.substr(0, equals);
  if (equals == std::string::npos || compare.key.empty())
    throw SceneError(compare.origin + ": write KEY=VALUE1,VALUE2 (like world.friction=true,false)");
  if (const std::string reason = unvariable_reason(compare.key); !reason.empty())
    throw SceneError(compare.origin + ": " + reason);
  std::string value;
  int depth = 0;
  bool quoted = false;
  auto add = [&] {
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t") + 1);
    if (value.empty()) throw SceneError(compare.origin + ": an empty value (two commas, or one at an end)");
    compare.values.push_back(value);
    compare.labels.push_back(compare.key + " = " + value);
    value.clear();
  };
  for (const char c : vary.substr(equals + 1)) {
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == '[' || c == '{')) ++depth;
    if (!quoted && (c == ']' || c == '}')) --depth;
    if (c == ',' && depth == 0 && !quoted) {
      add();
    } else {
      value += c;
    }
  }
  add();
  if (compare.values.size() < 2 || compare.values.size() > 4)
    throw SceneError(compare.origin + ": give two to four values, separated by commas");
  return compare;
}

void read_compare(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("compare");
  if (!t) return;
  TableReader r = top.child(*t, "[compare]");
  CompareSpec& compare = scene.compare;
  compare.origin = r.where(nullptr, "");  // "FILE:LINE: [compare]"
  compare.key = r.string("vary", "");
  if (compare.key.empty()) r.fail(nullptr, "vary", "missing: the field whose values the panes show, e.g. \"world.method\"");
  if (const std::string reason = unvariable_reason(compare.key); !reason.empty()) r.fail(r.get("vary"), "vary", reason);
  const toml::node* values = r.get("values");
  const toml::array* list = values ? values->as_array() : nullptr;
  if (!list || list->size() < 2 || list->size() > 4)
    r.fail(values, "values", "must be a list of two to four values of the field, one per pane");
  for (const toml::node& value : *list) {
    std::ostringstream text;
    value.visit([&](const auto& node) { text << node; });
    compare.values.push_back(text.str());
    compare.labels.push_back(compare.key + " = " + text.str());
  }
  if (const toml::node* labels = r.get("labels")) {
    const toml::array* names = labels->as_array();
    if (!names || names->size() != list->size() || !names->is_homogeneous(toml::node_type::string))
      r.fail(labels, "labels", "must be a list of strings, one per value");
    for (size_t i = 0; i < names->size(); ++i) compare.labels[i] = *names->get(i)->value<std::string>();
  }
  r.finish();
}

std::vector<Scene> load_variants(const SceneFile& file, const std::vector<std::string>& settings,
                                 const CompareSpec& compare) {
  std::vector<Scene> scenes;
  for (size_t i = 0; i < compare.values.size(); ++i) {
    std::vector<std::string> pane_settings = settings;
    pane_settings.push_back(compare.key + "=" + compare.values[i]);
    try {
      scenes.push_back(file.scene(pane_settings));
    } catch (const SceneError& error) {
      throw SceneError(compare.origin + " value " + std::to_string(i + 1) + ": " + error.what(), error.place());
    }
    Scene& scene = scenes.back();
    scene.compare = CompareSpec{};
    std::erase_if(scene.checks, [&](const CheckSpec& check) { return check.pane != 0 && check.pane != int(i) + 1; });
  }
  return scenes;
}

}  // namespace impulse::demos
