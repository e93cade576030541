// Narrow phase of a box against a sphere and against a plane.
#include "physics/collide.h"
#include "physics/manifold.h"

#include <cmath>

namespace impulse::physics {

// A sphere (A) against a box (B): the closest point of the box to the sphere's centre, or, when
// the centre is inside the box, the nearest face.
int collide_sphere_box(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Mat3 rotation = b.orientation.toRotationMatrix();
  const Vec3& half = b.shape.half_extents;
  const Real radius = a.shape.radius;
  const Vec3 centre = rotation.transpose() * (a.position - b.position);  // in the box's frame
  const Vec3 closest = centre.cwiseMax(-half).cwiseMin(half);

  Vec3 normal, on_box;  // box frame
  Real separation;
  if (closest != centre) {
    const Vec3 d = centre - closest;
    const Real distance = d.norm();
    separation = distance - radius;
    if (separation > margin) return 0;
    normal = d / distance;
    on_box = closest;
  } else {
    // Inside: leave through the nearest face (the first of equals, for determinism).
    int axis = 0;
    Real depth = half.x() - std::abs(centre.x());
    for (int k = 1; k < 3; ++k) {
      const Real dk = half[k] - std::abs(centre[k]);
      if (dk < depth) axis = k, depth = dk;
    }
    const Real sign = centre[axis] < 0 ? -1 : 1;
    normal = Vec3::Zero();
    normal[axis] = sign;
    on_box = centre;
    on_box[axis] = sign * half[axis];
    separation = -depth - radius;
  }
  const Vec3 world_normal = rotation * normal;
  const Vec3 on_sphere = a.position - world_normal * radius;
  out.push_back({ia, ib, (b.position + rotation * on_box + on_sphere) / 2, world_normal, separation, feature::corner(0)});
  return 1;
}

// A box (A) against a plane (B): each corner of the box's face that looks most against the plane
// (the incident face, as a box against a reference face is clipped) below the plane plus the
// margin. The lowest corner is always one of them. All eight, reduced to four by area, would mix
// the corners of a thin box's two faces as it lies nearly flat: a domino slapping down would keep
// its top face's far corners and leave a bottom corner untracked, to be found deep in the ground.
int collide_box_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Mat3 rotation = a.orientation.toRotationMatrix();
  const Vec3& n = b.shape.normal;
  const Vec3 local_n = rotation.transpose() * n;
  // Cheap rejection: the box's lowest reach along n.
  const Real reach = local_n.cwiseAbs().dot(a.shape.half_extents);
  if (n.dot(a.position) - b.shape.offset - reach > margin) return 0;
  int axis = 0;
  local_n.cwiseAbs().maxCoeff(&axis);
  const int face_bit = local_n[axis] > 0 ? 0 : 1 << axis;  // the corners whose `axis` side is against n

  const size_t first = out.size();
  for (int i = 0; i < 8; ++i) {
    if ((i & (1 << axis)) != face_bit) continue;
    const Vec3 corner = a.position + rotation * box_corner(a.shape.half_extents, i);
    const Real separation = n.dot(corner) - b.shape.offset;
    if (separation > margin) continue;
    out.push_back({ia, ib, corner - n * (separation / 2), n, separation, feature::corner(i)});
  }
  Vec3 t1, t2;  // across the plane's normal, fixed with the plane
  tangent_basis(n, t1, t2);
  return reduce_manifold(out, first, n, a.position, search_direction(t1, t2));
}

}  // namespace impulse::physics
