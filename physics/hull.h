// A convex hull: the polyhedron of a "hull" shape, in its body's frame.
#pragma once
#include "physics/math.h"

#include <memory>
#include <span>
#include <vector>

namespace impulse::physics {

struct HullFace {
  Vec3 normal = Vec3::UnitY();  // outward, unit
  Real offset = 0;              // dot(normal, x) = offset on the face: its distance from the origin
  int first = 0, count = 0;     // its corners, Hull::face_corners[first, first + count), counter-clockwise seen from outside
  // Four points on its sides that stand for a face of more corners where it touches (a pair keeps
  // four contact points): counter-clockwise, along the face's principal axes from its centre, each
  // ray scaled by the face's spread that way. Four corners of a pentagon would leave one side of it
  // unsupported, 0.31 of its radius from its centre; these leave a regular polygon's centre more
  // than half its apothem from each of their sides.
  Vec3 quad[4];
};

struct Hull {
  std::vector<Vec3> corners;
  std::vector<HullFace> faces;
  std::vector<int> face_corners;
  Real volume = 0;
  Real area = 0;
  // Per unit mass about the origin, in this frame: through the volume, and over the surface.
  Mat3 unit_inertia = Mat3::Zero();
  Mat3 unit_shell_inertia = Mat3::Zero();

  int corner_of(const HullFace& face, int k) const { return face_corners[face.first + k]; }
};

// The convex hull of `points` (qhull), coplanar faces merged into one polygon, in the points' own
// frame. Throws std::invalid_argument when they span no solid (fewer than four points off one plane).
Hull convex_hull(std::span<const Vec3> points);

// Where a body made of `points` has its centre of mass and principal axes: the hull moved there
// (its corners in those axes, from that centre) and the frame that takes it back to the points'
// own: x_points = centre + frame x_hull. `shell`: the mass on the surface, whose centre and axes
// may differ from the volume's.
struct PlacedHull {
  std::shared_ptr<const Hull> hull;
  Vec3 centre = Vec3::Zero();
  Quat frame = Quat::Identity();
};
PlacedHull place_hull(std::span<const Vec3> points, bool shell);

// The named solids a scene can ask for, their corners about their own frame (y up):
// a wedge of size [x, y, z]: the right triangle in x-y (its right angle at (-x/2, -y/2)) drawn along z;
// a regular tetrahedron of edge `size`, one face down; a prism of `sides` sides, its axis along y,
// `radius` to its corners and `height`.
std::vector<Vec3> wedge_points(const Vec3& size);
std::vector<Vec3> tetrahedron_points(Real edge);
std::vector<Vec3> prism_points(int sides, Real radius, Real height);

}  // namespace impulse::physics
