// Collision shapes and their mass properties.
#pragma once
#include "physics/hull.h"
#include "physics/mesh.h"
#include "physics/math.h"

#include <memory>
#include <string>

namespace impulse::physics {

// The order is collide()'s: a pair is dispatched with A the earlier type.
enum class ShapeType { sphere, box, capsule, cylinder, hull, mesh, plane };
// Its name as a scene file writes it ("sphere", ..., "plane").
const char* shape_name(ShapeType type);

// A shape in its body's local frame. A plane is static only: the points x with
// dot(normal, x) = offset, solid below (the side opposite the normal). A capsule is the points
// within `radius` of the segment from -half_height to +half_height along the body's y (Bullet's,
// Jolt's and MuJoCo's: `height`, the segment's length, leaves out the caps); a cylinder has its
// axis along y and its flat faces at y = +-half_height. A hull's corners are about its centre of
// mass, in its principal axes (hull.h's place_hull). A mesh is static only, as a plane: its
// triangles in its body's frame (mesh.h), solid nowhere, touched from each triangle's front.
struct Shape {
  ShapeType type = ShapeType::sphere;
  Real radius = 0.5;                   // sphere, capsule, cylinder
  Real half_height = 0.5;              // capsule, cylinder
  Vec3 half_extents{0.5, 0.5, 0.5};    // box
  Vec3 normal{0, 1, 0};                // plane, world space
  Real offset = 0;                     // plane
  // A hull's Hull or a mesh's Mesh: one pointer for both, so that a Body stays 512 bytes, eight
  // cache lines.
  std::shared_ptr<const void> data;

  const Hull* hull() const { return type == ShapeType::hull ? static_cast<const Hull*>(data.get()) : nullptr; }
  const Mesh* mesh() const { return type == ShapeType::mesh ? static_cast<const Mesh*>(data.get()) : nullptr; }
  std::shared_ptr<const Hull> shared_hull() const { return {data, hull()}; }  // sharing data's ownership
  std::shared_ptr<const Mesh> shared_mesh() const { return {data, mesh()}; }

  static Shape sphere(Real r) { Shape s; s.type = ShapeType::sphere; s.radius = r; return s; }
  static Shape box(const Vec3& h) { Shape s; s.type = ShapeType::box; s.half_extents = h; return s; }
  static Shape capsule(Real r, Real half) { Shape s; s.type = ShapeType::capsule; s.radius = r; s.half_height = half; return s; }
  static Shape cylinder(Real r, Real half) { Shape s; s.type = ShapeType::cylinder; s.radius = r; s.half_height = half; return s; }
  static Shape convex(std::shared_ptr<const Hull> h) { Shape s; s.type = ShapeType::hull; s.data = std::move(h); return s; }
  static Shape surface(std::shared_ptr<const Mesh> m) { Shape s; s.type = ShapeType::mesh; s.data = std::move(m); return s; }
  static Shape plane(const Vec3& n, Real d) { Shape s; s.type = ShapeType::plane; s.normal = n; s.offset = d; return s; }
};

// Corner `index` (0..7) of a box of half extents `half` centred on the origin: bits 0, 1, 2 of
// the index set mean +x, +y, +z. Collision feature ids name corners by this index.
inline Vec3 box_corner(const Vec3& half, int index) {
  return {index & 1 ? half.x() : -half.x(), index & 2 ? half.y() : -half.y(), index & 4 ? half.z() : -half.z()};
}

// Volume and the inertia tensor of unit density about the centre, in the local frame.
Real shape_volume(const Shape& shape);
Mat3 shape_unit_inertia(const Shape& shape);  // multiply by mass
// The same for a thin shell, the mass on the surface: a sphere's 2/3 R^2 (5/3 of the solid's); a
// box's six faces, each a thin plate with its share of the area; a cylinder's curved side alone (a
// ring or tube: m R^2 about its axis); a capsule's side and caps.
Mat3 shape_unit_shell_inertia(const Shape& shape);

// How far the shape, turned by `orientation`, reaches from its centre along the unit direction `d`:
// its support distance (a plane: 0; a mesh: its farthest vertex's).
Real reach_along(const Shape& shape, const Quat& orientation, const Vec3& d);
// Distance from the centre to the farthest point of the shape (0 for a plane; a mesh: its farthest vertex).
Real bounding_radius(const Shape& shape);
// Half the shape's thinnest size: a sphere's or capsule's radius, a box's smallest half extent, the
// smaller of a cylinder's radius and half height, a hull's nearest face from its centre (a plane:
// infinite, a mesh too).
Real thinnest_half_size(const Shape& shape);

// Why a shape is impossible ("radius must be > 0, got -1"), or empty when it is fine.
std::string shape_problem(const Shape& shape);

}  // namespace impulse::physics
