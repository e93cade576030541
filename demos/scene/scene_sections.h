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
// Static bodies without a colour of their own (a wall, a ramp): a neutral grey, so that the eye
// goes to what moves.
inline constexpr Colour kStaticColour{0.62f, 0.63f, 0.66f};

// Absurd magnitudes are refused, with the reason: what a lecture's scene needs is far below them,
// and above them the numbers stop meaning what they say.
inline constexpr double kLargestSize = 1000;  // m, a radius or an edge
inline constexpr double kLargestMass = 1e9;   // kg, or kg/m^3 for a density
inline constexpr double kFarthest = 1e4;      // m from the origin
inline constexpr const char* kFarthestWhy = "beyond, the drawing's float coordinates lose millimetres";
inline constexpr double kFastest = 1000;      // m/s
inline constexpr const char* kFastestWhy =
    "faster, a body moves over 16 m in a 60 Hz step and passes through others unseen (tunnelling)";
inline constexpr double kFastestSpin = 1000;  // rad/s
inline constexpr const char* kFastestSpinWhy = "faster, a body turns over a quarter turn in a sub-step";

void read_world(TableReader& top, Scene& scene);   // [world]
void read_bodies(TableReader& top, Scene& scene);  // [[body]]
void read_patterns(TableReader& top, Scene& scene);  // [[pyramid]], [[lattice]]: many bodies at once
void read_joints(TableReader& top, Scene& scene);  // [[joint]], after the bodies they name
void read_material_pairs(TableReader& top, Scene& scene);  // [[material_pair]], after the bodies
// A body's `planar = "xy"` (or "yz", "xz", "none"): the world axis its plane is normal to
// (physics/planar.h), else `fallback`, the world's.
int read_planar(TableReader& r, int fallback);
// A "mesh" body's OBJ file, its coordinates multiplied by `scale` (scene_mesh.cpp). Throws
// std::runtime_error saying why it cannot be read.
std::shared_ptr<const physics::Mesh> read_mesh_file(const std::string& path, double scale);
// A body's `material = "NAME"`, if it has one: its kind (physics/materials.h), a new one for a new name.
void read_material_kind(TableReader& r, Scene& scene, physics::BodyDef& def);
void read_view(TableReader& top, Scene& scene);
void read_compare(TableReader& top, Scene& scene);  // [compare], before the checks that name a pane
void read_captions(TableReader& top, Scene& scene);  // [[caption]], after [compare]: a caption may name a pane
void read_checks(TableReader& top, Scene& scene);  // [[check]], after the bodies they name    // [camera], [video], [draw], [overlay], [[caption]], [playback]
void read_equations(TableReader& top, Scene& scene);  // [[equation]], after [playback] and [compare]

}  // namespace impulse::demos
