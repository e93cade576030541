// Comparisons: one scene shown as two to four panes side by side (demos/film/film.h), one per value
// of one field, from a scene file's [compare] table or from `impulse compare --vary KEY=V1,V2`.
//
//   [compare]
//   vary = "world.method"                       # a field, as --set names it
//   values = ["projection", "impulse", "penalty"]
//   labels = ["projection", "impulse (the default)", "penalty"]   # optional
//
// Every pane shares the camera, the video, the playback and the duration, so those fields cannot
// be varied.
#pragma once
#include "demos/scene/scene_file.h"

#include <string>
#include <vector>

namespace impulse::demos {

// What is wrong with varying `key` in a comparison ("" when nothing is).
std::string unvariable_reason(const std::string& key);

// --vary KEY=V1,V2[,...]: a comma inside brackets or quotes is part of its value
// (body[0].velocity=[1, 0, 0],[2, 0, 0]). Throws SceneError naming the argument.
CompareSpec compare_from_vary(const std::string& vary);

// The scenes of a comparison, one per value: each is read from the parsed file with `settings`
// and KEY=VALUE over it, keeping the [[check]]s about its pane (pane 0 or its number), without
// [compare]. A value the field refuses is reported with `compare.origin`.
//
// A varied restitution or friction is seen only through the pairs' materials (physics/materials.h:
// the larger restitution, the geometric mean of the frictions, or a [[material_pair]]'s): when
// every pair a varied body can meet gets the same material in every pane, the comparison shows
// nothing and is refused with the reason.
std::vector<Scene> load_variants(const SceneFile& file, const std::vector<std::string>& settings,
                                 const CompareSpec& compare);

// Panes that meet with the same materials everywhere although their values differ (the others
// do not): "panes 1 and 2 ...", with the reason; one line each, for stderr.
std::vector<std::string> compare_warnings(const std::vector<Scene>& panes, const CompareSpec& compare);

}  // namespace impulse::demos
