// The parts of a scene file, each read by its own file: bodies and world (physics), and what the
// video shows (camera, video, draw).
#pragma once
#include "demos/scene_file.h"
#include "demos/table_reader.h"

namespace impulse::demos {

void read_world(TableReader& top, Scene& scene);   // [world]
void read_bodies(TableReader& top, Scene& scene);  // [[body]]
void read_view(TableReader& top, Scene& scene);    // [camera], [video], [draw]

}  // namespace impulse::demos
