// Narrow phase of capsules and cylinders against a sphere and against a plane: closest points by
// formula. Their pairs with boxes, capsules and cylinders are collide_convex.cpp's.
#include "physics/collide.h"
#include "physics/manifold.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impulse::physics {

namespace {

// A sphere (A) against the closest point `on_b` of B's surface (world), or, where the centre is
// inside B, B's surface point `on_b` with the outward `inside_normal` and the centre's depth.
int sphere_against(const Body& a, int ia, int ib, const Vec3& on_b, bool inside, const Vec3& inside_normal, Real depth, Real margin,
                   bool round_b, std::vector<Contact>& out) {
  const Real radius = a.shape.radius;
  Vec3 normal = inside_normal;
  Real separation = -depth - radius;
  if (!inside) {
    const Vec3 d = a.position - on_b;
    const Real distance = d.norm();
    separation = distance - radius;
    if (separation > margin) return 0;
    normal = distance > Real(1e-12) ? Vec3(d / distance) : inside_normal;
  }
  const Vec3 on_sphere = a.position - normal * radius;
  out.push_back({ia, ib, (on_b + on_sphere) / 2, normal, separation, feature::round_point(0, true, round_b)});
  return 1;
}

}  // namespace

// A sphere (A) against a capsule (B): against the closest point of B's segment, a sphere.
int collide_sphere_capsule(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Vec3 axis = rotate(b.orientation, Vec3::UnitY());
  const Real t = std::clamp(axis.dot(a.position - b.position), -b.shape.half_height, b.shape.half_height);
  const Vec3 core = b.position + t * axis;
  const Vec3 d = a.position - core;
  const Real distance = d.norm();
  Vec3 normal;
  if (distance > Real(1e-12)) {
    normal = d / distance;
  } else {  // the centre on the segment: out across the axis, any way
    Vec3 t1, t2;
    tangent_basis(axis, t1, t2);
    normal = t1;
  }
  const Vec3 on_b = core + normal * b.shape.radius;
  const bool inside = distance < b.shape.radius;
  return sphere_against(a, ia, ib, on_b, inside, normal, b.shape.radius - distance, margin, true, out);
}

// A sphere (A) against a cylinder (B): the closest point of the solid cylinder to the centre, or,
// from inside, the nearest of its side and two faces.
int collide_sphere_cylinder(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Mat3 rotation = b.orientation.toRotationMatrix();
  const Vec3 c = rotation.transpose() * (a.position - b.position);  // in the cylinder's frame
  const Real r = b.shape.radius, h = b.shape.half_height;
  const Real across = std::hypot(c.x(), c.z());
  const Vec3 out_side = across > Real(1e-12) ? Vec3(c.x() / across, 0, c.z() / across) : Vec3::UnitX();
  const bool inside = across <= r && std::abs(c.y()) <= h;
  if (!inside) {
    const Vec3 closest = across > r ? Vec3(out_side.x() * r, std::clamp(c.y(), -h, h), out_side.z() * r) : Vec3(c.x(), std::clamp(c.y(), -h, h), c.z());
    // On the side (not past a face): round there.
    const bool round = std::abs(c.y()) < h;
    return sphere_against(a, ia, ib, b.position + rotation * closest, false, Vec3::UnitY(), 0, margin, round, out);
  }
  const Real to_side = r - across, to_face = h - std::abs(c.y());
  if (to_face <= to_side) {
    const Vec3 n(0, c.y() < 0 ? -1 : 1, 0);
    const Vec3 on(c.x(), n.y() * h, c.z());
    return sphere_against(a, ia, ib, b.position + rotation * on, true, rotation * n, to_face, margin, false, out);
  }
  const Vec3 on(out_side.x() * r, c.y(), out_side.z() * r);
  return sphere_against(a, ia, ib, b.position + rotation * on, true, rotation * out_side, to_side, margin, true, out);
}

// A capsule (A) against a plane (B): each end's ball, as a sphere against the plane.
int collide_capsule_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Vec3& n = b.shape.normal;
  const Vec3 axis = rotate(a.orientation, Vec3::UnitY());
  int added = 0;
  for (int end = 0; end < 2; ++end) {
    const Vec3 centre = a.position + (end == 0 ? -a.shape.half_height : a.shape.half_height) * axis;
    const Real height = n.dot(centre) - b.shape.offset;
    const Real separation = height - a.shape.radius;
    if (separation > margin) continue;
    out.push_back({ia, ib, centre - n * ((height + a.shape.radius) / 2), n, separation, feature::round_point(end, true, false)});
    ++added;
  }
  return added;
}

// A cylinder (A) against a plane (B): on each flat face's rim, the point lowest along the normal
// (a cylinder on its side touches along a line: its two ends), and on a face that looks at the
// plane four rim points fixed in the body, so that a cylinder standing on it rests on four; those
// below the plane plus the margin, cut to four. Rim points: 0-3 and 4-7 the two faces' fixed ones, 8 and 9 the lowest.
int collide_cylinder_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Vec3& n = b.shape.normal;
  const Mat3 rotation = a.orientation.toRotationMatrix();
  const Vec3 axis = rotation.col(1);
  const Real r = a.shape.radius, h = a.shape.half_height;
  // Cheap rejection: the lowest reach along n.
  const Real axial = std::abs(axis.dot(n)), radial = std::sqrt(std::max(Real(1) - axial * axial, Real(0)));
  if (n.dot(a.position) - b.shape.offset - (h * axial + r * radial) > margin) return 0;
  const size_t first = out.size();
  const Vec3 down = -(n - axis * axis.dot(n));  // across the axis, away from the plane
  const Real down_length = down.norm();
  for (int face = 0; face < 2; ++face) {
    const Real sign = face == 0 ? -1 : 1;
    const Vec3 centre = a.position + sign * h * axis;
    auto add = [&](const Vec3& point, int index, bool round) {
      const Real separation = n.dot(point) - b.shape.offset;
      if (separation > margin) return;
      out.push_back({ia, ib, point - n * (separation / 2), n, separation, feature::round_point(index, round, false)});
    };
    // The fixed points only where a face looks at the plane: rolling on its side, they would come
    // and go as they pass under the axis.
    // The lowest point too, unless a fixed one is there already (a tenth of the radius away).
    bool lowest_fixed = down_length <= Real(1e-9);
    const Vec3 lowest = lowest_fixed ? centre : Vec3(centre + r * down / down_length);
    for (int k = 0; k < 4 && sign * axis.dot(n) < Real(-0.5); ++k) {
      const Real angle = k * std::numbers::pi / 2;
      const Vec3 rim = centre + r * (std::cos(angle) * rotation.col(0) + std::sin(angle) * rotation.col(2));
      add(rim, 4 * face + k, false);
      lowest_fixed = lowest_fixed || (rim - lowest).norm() < Real(0.1) * r;
    }
    if (!lowest_fixed) add(lowest, 8 + face, true);
  }
  const int added = int(out.size() - first);
  if (added <= 4) return added;
  Vec3 t1, t2;  // across the plane's normal, fixed with the plane
  tangent_basis(n, t1, t2);
  return reduce_manifold(out, first, n, a.position, search_direction(t1, t2));
}

}  // namespace impulse::physics
