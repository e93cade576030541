// The parts of a scene file, each read by its own file: bodies and world (physics), and what the
// video shows (camera, video, draw).
#pragma once
#include "demos/scene_file.h"
#include "demos/table_reader.h"

namespace impulse::demos {

void read_world(TableReader& top, Scene& scene);   // [world]
void read_bodies(TableReader& top, Scene& scene);  // [[body]]
void read_patterns(TableReader& top, Scene& scene);  // [[pyramid]], [[lattice]]: many bodies at once
void read_joints(TableReader& top, Scene& scene);  // [[joint]], after the bodies they name
void read_view(TableReader& top, Scene& scene);    // [camera], [video], [draw], [overlay], [[caption]], [playback]

}  // namespace impulse::demos
