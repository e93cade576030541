// Per-instance data the mesh programs read (vertex attributes 2..10, see shaders.h), and how
// each DrawList item becomes instances of the unit meshes in mesh.h.
#pragma once
#include <vector>

#include "render/draw_list.h"

namespace impulse::render {

enum class InstanceStyle { plain = 0, spin_marks = 1, edges = 2 };

struct Instance {
  float model[16];          // column-major, unit mesh -> world
  float normal_matrix[9];   // column-major inverse transpose of the model's 3x3 part
  float colour[3];          // sRGB
  float style;              // InstanceStyle as a float attribute
};
static_assert(sizeof(Instance) == 29 * sizeof(float), "Instance must stay tightly packed");

Instance sphere_instance(const SphereItem& sphere);  // of make_icosphere
Instance box_instance(const BoxItem& box);           // of make_cube

struct ArrowInstances {
  Instance shaft;  // of make_cylinder
  Instance head;   // of make_cone
};
// Shaft and head sizes grow with the arrow's length up to a limit, so short arrows stay arrows
// and long ones stay slim. Returns false (and nothing) for an arrow shorter than 1e-5 m.
bool arrow_instances(const ArrowItem& arrow, ArrowInstances& out);

}  // namespace impulse::render
