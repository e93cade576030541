// [[check]] tables (scene_checks.h has what each kind measures).
#include "demos/scene/scene_sections.h"

namespace impulse::demos {

void read_checks(TableReader& top, Scene& scene) {
  const toml::array* checks = top.table_list("check");
  if (!checks) return;
  int index = 0;
  for (const toml::node& item : *checks) {
    ++index;
    TableReader r(*item.as_table(), scene.path, "[[check]] " + std::to_string(index));
    CheckSpec check;
    check.kind = r.choice("kind", "", {"momentum", "energy", "at_rest", "inside", "velocity", "height", "drift", "penetration"});
    const bool needs_body = check.kind == "at_rest" || check.kind == "inside" || check.kind == "velocity" ||
                            check.kind == "height" || check.kind == "drift";
    const std::string body = r.string("body", "");
    if (needs_body) {
      if (body.empty()) r.fail(nullptr, "body", "missing: the name of the body it is about");
      check.body = find_body(scene, body);
      if (check.body < 0) r.fail(r.get("body"), "body", "no body is named '" + body + "'");
    }
    check.from = r.number("from", 0, 0);
    check.to = r.number("to", scene.duration, 0);
    if (check.to < check.from) r.fail(r.get("to"), "to", "must not come before `from`");
    check.tolerance = r.number("tolerance", check.kind == "energy" ? 0.01 : 1e-6, 0);
    check.speed = r.number("speed", 0.01, 0, INFINITY, true);
    check.distance = r.number("distance", 0.01, 0);
    check.depth = r.number("depth", 0.01, 0);
    check.ratio = r.number("ratio", 0, 0);
    if (check.kind == "height") {  // heights in metres
      check.min.y() = r.number("min", check.min.y());
      check.max.y() = r.number("max", check.max.y());
    } else {  // positions
      check.min = r.vec3("min", check.min);
      check.max = r.vec3("max", check.max);
    }
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
