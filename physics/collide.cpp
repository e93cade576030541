// Narrow phase dispatch, and the sphere pairs without a box.
#include "physics/collide.h"

namespace impulse::physics {

int collide_spheres(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Vec3 d = a.position - b.position;  // from B's centre to A's centre
  const Real distance = d.norm();
  const Real separation = distance - a.shape.radius - b.shape.radius;
  if (separation > margin) return 0;
  const Vec3 normal = distance > Real(1e-12) ? Vec3(d / distance) : Vec3::UnitY();
  const Vec3 surface_a = a.position - normal * a.shape.radius;
  const Vec3 surface_b = b.position + normal * b.shape.radius;
  out.push_back({ia, ib, (surface_a + surface_b) / 2, normal, separation, 0});
  return 1;
}

int collide_sphere_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Vec3& n = b.shape.normal;
  const Real height = n.dot(a.position) - b.shape.offset;  // centre above the plane
  const Real separation = height - a.shape.radius;
  if (separation > margin) return 0;
  const Vec3 on_plane = a.position - n * height;
  const Vec3 on_sphere = a.position - n * a.shape.radius;
  out.push_back({ia, ib, (on_plane + on_sphere) / 2, n, separation, 0});
  return 1;
}

int collide(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out, SatCache* cache) {
  if (a.shape.type > b.shape.type) return collide(b, ib, a, ia, margin, out);
  using enum ShapeType;
  switch (a.shape.type) {
    case sphere:
      switch (b.shape.type) {
        case sphere: return collide_spheres(a, ia, b, ib, margin, out);
        case box: return collide_sphere_box(a, ia, b, ib, margin, out);
        case capsule: return collide_sphere_capsule(a, ia, b, ib, margin, out);
        case cylinder: return collide_sphere_cylinder(a, ia, b, ib, margin, out);
        case hull: return collide_sphere_hull(a, ia, b, ib, margin, out);
        case mesh: return collide_sphere_mesh(a, ia, b, ib, margin, out);
        case plane: return collide_sphere_plane(a, ia, b, ib, margin, out);
      }
      break;
    case box:
      if (b.shape.type == mesh) return collide_convex_mesh(a, ia, b, ib, margin, out);
      if (b.shape.type == box) return collide_boxes(a, ia, b, ib, margin, out, cache);
      if (b.shape.type == plane) return collide_box_plane(a, ia, b, ib, margin, out);
      return collide_convex(a, ia, b, ib, margin, out);
    case capsule:
      if (b.shape.type == mesh) return collide_convex_mesh(a, ia, b, ib, margin, out);
      if (b.shape.type == plane) return collide_capsule_plane(a, ia, b, ib, margin, out);
      return collide_convex(a, ia, b, ib, margin, out);
    case cylinder:
      if (b.shape.type == mesh) return collide_convex_mesh(a, ia, b, ib, margin, out);
      if (b.shape.type == plane) return collide_cylinder_plane(a, ia, b, ib, margin, out);
      return collide_convex(a, ia, b, ib, margin, out);
    case hull:
      if (b.shape.type == mesh) return collide_convex_mesh(a, ia, b, ib, margin, out);
      if (b.shape.type == plane) return collide_hull_plane(a, ia, b, ib, margin, out);
      return collide_convex(a, ia, b, ib, margin, out);
    case mesh:
    case plane:
      break;  // meshes and planes are static: two never meet
  }
  return 0;
}

}  // namespace impulse::physics
