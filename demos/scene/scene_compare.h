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
std::vector<Scene> load_variants(const SceneFile& file, const std::vector<std::string>& settings,
                                 const CompareSpec& compare);

}  // namespace impulse::demos
