// [[check]] tables (scene_checks.h has what each kind measures).
#include "demos/scene/scene_sections.h"

#include <algorithm>
#include <string>
#include <vector>

namespace impulse::demos {

namespace {

// The fields that bound each kind of check. A check measures against its own and refuses any
// other kind's: a `speed` on an "inside" check would otherwise be read and never used.
const std::vector<std::string> kCriteria = {"tolerance", "speed", "distance", "depth", "ratio", "min", "max"};
std::vector<std::string> criteria_of(const std::string& kind) {
  if (kind == "momentum" || kind == "energy") return {"tolerance"};
  if (kind == "at_rest") return {"speed"};
  if (kind == "inside" || kind == "velocity") return {"min", "max"};
  if (kind == "height") return {"min", "max", "ratio", "tolerance"};
  if (kind == "drift") return {"distance"};
  return {"depth"};  // penetration
}

// The kind's bounds. Kinds whose bounds have no default ("inside", "velocity", "height") refuse a
// check without one: with none, it could not fail.
void read_criterion(TableReader& r, CheckSpec& check) {
  const std::vector<std::string> own = criteria_of(check.kind);
  std::string listed;
  for (const std::string& field : own) listed += (listed.empty() ? "`" : ", `") + field + "`";
  for (const std::string& field : kCriteria)
    if (std::find(own.begin(), own.end(), field) == own.end() && r.gives(field))
      r.fail(r.get(field), field, "a check of kind \"" + check.kind + "\" does not use it (its bounds: " + listed + ")");

  const std::string& kind = check.kind;
  if (kind == "momentum" || kind == "energy") check.tolerance = r.number("tolerance", kind == "energy" ? 0.01 : 1e-6, 0);
  if (kind == "at_rest") check.speed = r.number("speed", 0.01, 0, INFINITY, true);
  if (kind == "drift") check.distance = r.number("distance", 0.01, 0);
  if (kind == "penetration") check.depth = r.number("depth", 0.01, 0);
  if (kind == "inside" || kind == "velocity") {  // positions or velocities
    if (!r.has("min") && !r.has("max"))
      r.fail(nullptr, "min", "missing: a check of kind \"" + kind + "\" needs `min` or `max`, else it cannot fail");
    check.min = r.vec3("min", check.min);
    check.max = r.vec3("max", check.max);
  }
  if (kind == "height") {  // heights in metres, or a share of the starting height
    if (!r.has("min") && !r.has("max") && !r.has("ratio"))
      r.fail(nullptr, "min", "missing: a check of kind \"height\" needs `min`, `max` or `ratio`, else it cannot fail");
    if (r.has("ratio") && (r.has("min") || r.has("max")))
      r.fail(r.get("ratio"), "ratio", "give `ratio` (with `tolerance`) or `min` and `max`, not both");
    if (r.has("tolerance") && !r.has("ratio"))
      r.fail(r.get("tolerance"), "tolerance", "bounds `ratio` only: give `ratio` too, or bound the height with `min` and `max`");
    check.ratio = r.number("ratio", 0, 0, INFINITY, true);
    check.tolerance = r.number("tolerance", 1e-6, 0);
    check.min.y() = r.number("min", check.min.y());
    check.max.y() = r.number("max", check.max.y());
  }
  if ((check.min.array() > check.max.array()).any()) r.fail(r.get("max"), "max", "must not be below `min`");
}

}  // namespace

void read_checks(TableReader& top, Scene& scene) {
  const toml::array* checks = top.table_list("check");
  if (!checks) return;
  int index = 0;
  for (const toml::node& item : *checks) {
    ++index;
    TableReader r = top.child(*item.as_table(), "[[check]] " + std::to_string(index));
    CheckSpec check;
    check.kind = r.choice("kind", "", {"momentum", "energy", "at_rest", "inside", "velocity", "height", "drift", "penetration"});
    const bool needs_body = check.kind == "at_rest" || check.kind == "inside" || check.kind == "velocity" ||
                            check.kind == "height" || check.kind == "drift";
    const std::string body = r.string("body", "");
    if (needs_body) {
      if (body.empty()) r.fail(nullptr, "body", "missing: the name of the body it is about");
      check.body = find_body(scene, body);
      if (check.body < 0) r.fail(r.get("body"), "body", "no body is named '" + body + "'");
    } else if (r.has("body")) {
      r.fail(r.get("body"), "body", "a check of kind \"" + check.kind + "\" is about every body, not one");
    }
    check.from = r.number("from", 0, 0);
    check.to = r.number("to", scene.duration, 0);
    if (check.to < check.from) r.fail(r.get("to"), "to", "must not come before `from`");
    read_criterion(r, check);
    const int panes = int(scene.compare.values.size());
    check.pane = r.integer("pane", 0, 0, 4);
    if (check.pane > panes)
      r.fail(r.get("pane"), "pane", panes == 0 ? "the scene has no [compare] table, so no panes"
                                                : "the [compare] table has " + std::to_string(panes) + " panes");
    r.finish();
    check.text = "[[check]] " + std::to_string(index) + " (" + check.kind + (body.empty() ? "" : " of '" + body + "'") + ")";
    scene.checks.push_back(check);
  }
}

}  // namespace impulse::demos
