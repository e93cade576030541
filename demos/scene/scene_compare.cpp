#include "demos/scene/scene_compare.h"

#include "demos/scene/scene_sections.h"

#include "physics/materials.h"

#include <charconv>
#include <cstdio>
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

namespace {

// A value as the file wrote it, for --set and for the panes' labels: a float in its shortest
// form that reads back the same (0.2, not 0.20000000000000001; 1.0, not 1), a list item by item.
std::string value_text(const toml::node& value) {
  if (const toml::array* list = value.as_array()) {
    std::string text = "[";
    for (size_t i = 0; i < list->size(); ++i) text += (i ? ", " : "") + value_text(*list->get(i));
    return text + "]";
  }
  if (const auto* number = value.as_floating_point()) {
    char digits[32];
    const auto end = std::to_chars(digits, digits + sizeof digits, number->get()).ptr;
    const std::string text(digits, end);
    return text.find_first_not_of("-0123456789") == std::string::npos ? text + ".0" : text;  // 1.0 stays a float
  }
  std::ostringstream text;
  value.visit([&](const auto& node) { text << node; });
  return text.str();
}

// `text` with each {value} and {label} replaced by the pane's.
void name_the_pane(std::string& text, const std::string& value, const std::string& label) {
  for (const auto& [name, with] : {std::pair{std::string("{value}"), value}, std::pair{std::string("{label}"), label}})
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + with.size())) text.replace(at, name.size(), with);
}

// Plain text for LaTeX's \text{}: its special characters written as themselves.
std::string tex_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') out += "\\textbackslash{}";
    else if (c == '^' || c == '~') out += std::string("\\") + c + "{}";
    else if (std::string_view("{}_%&#$").find(c) != std::string_view::npos) out += std::string("\\") + c;
    else out += c;
  }
  return out;
}

}  // namespace

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
    compare.values.push_back(value_text(value));
    compare.labels.push_back(compare.key + " = " + compare.values.back());
  }
  if (const toml::node* labels = r.get("labels")) {
    const toml::array* names = labels->as_array();
    if (!names || names->size() != list->size() || !names->is_homogeneous(toml::node_type::string))
      r.fail(labels, "labels", "must be a list of strings, one per value");
    for (size_t i = 0; i < names->size(); ++i) compare.labels[i] = *names->get(i)->value<std::string>();
  }
  r.finish();
}

namespace {

// Whether two panes meet with the same materials in every pair that can touch (not two still
// bodies); if not, `differs` is left alone. `why`: a pair that hides the difference between them,
// in words ("'bob' meets 'block' with the larger restitution, the block's 0.5").
bool same_contacts(const Scene& a, const Scene& b, std::string& why) {
  const size_t n = std::min(a.bodies.size(), b.bodies.size());
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (a.bodies[i].is_static && a.bodies[j].is_static) continue;
      const physics::ContactMaterial ma = physics::contact_material(a.bodies[i].material, a.bodies[j].material, a.world.pair_materials);
      const physics::ContactMaterial mb = physics::contact_material(b.bodies[i].material, b.bodies[j].material, b.world.pair_materials);
      if (ma.friction != mb.friction || ma.restitution != mb.restitution) return false;
    }
  // Where the bodies' own values differ, say what hid it.
  for (size_t i = 0; i < n && why.empty(); ++i) {
    const physics::Material &x = a.bodies[i].material, &y = b.bodies[i].material;
    if (x.restitution == y.restitution && x.friction == y.friction) continue;
    for (size_t j = 0; j < n && why.empty(); ++j) {
      if (j == i || (a.bodies[i].is_static && a.bodies[j].is_static)) continue;
      const physics::Material& other = a.bodies[j].material;
      char text[256];
      if (x.restitution != y.restitution && other.restitution >= std::max(x.restitution, y.restitution))
        std::snprintf(text, sizeof text, "'%s' meets '%s' with the larger restitution of the two, the %s's %g",
                      a.bodies[i].name.c_str(), a.bodies[j].name.c_str(), a.bodies[j].name.c_str(), double(other.restitution));
      else if (x.friction != y.friction && other.friction == 0)
        std::snprintf(text, sizeof text, "'%s' meets '%s', whose friction is 0: the pair's is the geometric mean, 0",
                      a.bodies[i].name.c_str(), a.bodies[j].name.c_str());
      else
        std::snprintf(text, sizeof text, "a [[material_pair]] sets what '%s' meets '%s' with", a.bodies[i].name.c_str(),
                      a.bodies[j].name.c_str());
      why = text;
    }
  }
  if (why.empty()) why = "every pair the varied bodies can touch gets the same material";
  return true;
}

// A body's (or a pattern's, or a material pair's) restitution or friction; not [world] friction, the
// switch for all contacts.
bool varies_material(const std::string& key) {
  if (key.rfind("world.", 0) == 0) return false;
  for (const char* field : {".restitution", ".friction"})
    if (key.size() > std::string(field).size() && key.compare(key.size() - std::string(field).size(), std::string::npos, field) == 0) return true;
  return false;
}

}  // namespace

std::vector<std::string> compare_warnings(const std::vector<Scene>& panes, const CompareSpec& compare) {
  std::vector<std::string> warnings;
  if (!varies_material(compare.key) || panes.empty()) return warnings;
  // A pane's restitution that every pair overrides: the body bounces with another's, larger.
  const Scene& first = panes[0];
  for (size_t i = 0; i < first.bodies.size(); ++i) {
    bool varied = false;
    for (const Scene& pane : panes) varied = varied || pane.bodies[i].material.restitution != first.bodies[i].material.restitution;
    if (!varied) continue;
    for (size_t p = 0; p < panes.size(); ++p) {
      const physics::Real own = panes[p].bodies[i].material.restitution;
      physics::Real least = 1e9;  // the least restitution it bounces with off anything it can touch
      size_t by = i;
      for (size_t j = 0; j < panes[p].bodies.size(); ++j) {
        if (j == i || (panes[p].bodies[i].is_static && panes[p].bodies[j].is_static)) continue;
        const physics::Real e =
            physics::contact_material(panes[p].bodies[i].material, panes[p].bodies[j].material, panes[p].world.pair_materials).restitution;
        if (e < least) least = e, by = j;
      }
      if (by == i || least <= own) continue;
      char text[512];
      std::snprintf(text, sizeof text,
                    ": warning: pane %zu (%s): '%s' bounces with %g at least, not %g: a pair takes the larger of its two "
                    "restitutions ('%s' has %g); set the other bodies' restitution too, or give the pair its own with a [[material_pair]]",
                    p + 1, compare.labels[p].c_str(), first.bodies[i].name.c_str(), double(least), double(own),
                    first.bodies[by].name.c_str(), double(least));
      warnings.push_back(compare.origin + text);
    }
  }
  for (size_t p = 0; p < panes.size(); ++p)
    for (size_t q = p + 1; q < panes.size(); ++q) {
      std::string why;
      if (same_contacts(panes[p], panes[q], why))
        warnings.push_back(compare.origin + ": warning: panes " + std::to_string(p + 1) + " and " + std::to_string(q + 1) +
                           " (" + compare.labels[p] + ", " + compare.labels[q] + ") will look the same: " + why);
    }
  return warnings;
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
    std::erase_if(scene.captions, [&](const CaptionCue& cue) { return cue.pane != 0 && cue.pane != int(i) + 1; });
    std::erase_if(scene.equations, [&](const EquationCue& cue) { return cue.pane != 0 && cue.pane != int(i) + 1; });
    for (CaptionCue& cue : scene.captions) {
      cue.own = cue.pane != 0 || names_the_pane(cue.text);
      name_the_pane(cue.text, compare.values[i], compare.labels[i]);
    }
    for (EquationCue& cue : scene.equations) name_the_pane(cue.tex, compare.values[i], "\\text{" + tex_text(compare.labels[i]) + "}");
  }
  if (varies_material(compare.key)) {
    bool all_same = true;
    std::string why;
    for (size_t i = 1; i < scenes.size() && all_same; ++i) all_same = same_contacts(scenes[0], scenes[i], why);
    if (all_same)
      throw SceneError(compare.origin + ": every pane meets with the same materials, so the comparison would show nothing: " + why +
                       ". Vary the other body's value too (--set), or give the pair its own with a [[material_pair]] " +
                       "(docs/scene_files.md)");
  }
  return scenes;
}

}  // namespace impulse::demos
