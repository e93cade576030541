// The parts of a scene file, each read by its own file: bodies and world (physics), and what the
// video shows (camera, video, draw).
#pragma once
#include "demos/scene/scene_file.h"
#include "demos/scene/table_reader.h"

namespace impulse::demos {

// Colour-blind-safe (Okabe and Ito), for bodies without a colour of their own; a pattern's rows
// take the first five in turn.
inline constexpr Colour kBodyPalette[] = {{0.90f, 0.62f, 0.00f}, {0.34f, 0.71f, 0.91f}, {0.00f, 0.62f, 0.45f},
                                          {0.80f, 0.47f, 0.65f}, {0.00f, 0.45f, 0.70f}, {0.94f, 0.89f, 0.26f}};
inline constexpr size_t kRowColourCount = 5;

void read_world(TableReader& top, Scene& scene);   // [world]
void read_bodies(TableReader& top, Scene& scene);  // [[body]]
void read_patterns(TableReader& top, Scene& scene);  // [[pyramid]], [[lattice]]: many bodies at once
void read_joints(TableReader& top, Scene& scene);  // [[joint]], after the bodies they name
void read_view(TableReader& top, Scene& scene);    // [camera], [video], [draw], [overlay], [[caption]], [playback]

}  // namespace impulse::demos
