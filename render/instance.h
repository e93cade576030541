// Per-instance data the mesh programs read (vertex attributes 2..10, see shaders.h), and how
// spheres, boxes, cylinders, flat meshes and points become instances of the meshes in mesh.h (or
// impostor quads).
#pragma once
#include <vector>

#include "render/draw_list.h"

namespace impulse::render {

// Bit flags, passed to the shaders as a float attribute (see shaders.cpp, kSurface).
enum InstanceStyle : int { plain = 0, spin_marks = 1, edges = 2, sleeping = 4 };

struct Instance {
  float model[16];          // column-major, unit mesh -> world
  float normal_matrix[9];   // column-major inverse transpose of the model's 3x3 part
  float colour[3];          // sRGB
  float style;              // InstanceStyle flags as a float attribute
};
static_assert(sizeof(Instance) == 29 * sizeof(float), "Instance must stay tightly packed");

Instance sphere_instance(const SphereItem& sphere);  // of make_icosphere, or an impostor quad
Instance box_instance(const BoxItem& box);           // of make_cube
// Of make_cylinder. Never `edges`: it darkens by unit-cube coordinates, which on the curved side
// would draw lines where x or z is +-1. `spin_marks` takes the sphere's octants of the unit
// cylinder's coordinates: x and z scale alike, so its sectors are a ball's of the same frame.
Instance cylinder_instance(const CylinderItem& cylinder);
// Of its own make_flat_mesh, unscaled: `edges` draws its faces' sides from the mesh's outline values.
Instance mesh_instance(const MeshItem& mesh);
Instance point_instance(const Vec3f& position, float radius, const Colour& colour);  // a plain sphere

}  // namespace impulse::render
