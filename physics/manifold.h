// Contact manifolds: how a pair's points are named (feature ids) and cut down to four.
#pragma once
#include "physics/contact.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

// A contact's `feature` names the pair of geometric features that made it, so that the same
// point keeps its id from step to step while the same features touch (the world keys warm
// starting on (body_a, body_b, feature)). Every id fits in 16 bits:
//
//   bits 14-15  kind
//   kind 0  single point (sphere pairs: 0) or box corner against a plane: bits 0-2 = corner
//   kind 1  face contact between boxes: bit 12 = reference box (0 = A, 1 = B), bits 9-11 =
//           reference face, bits 0-6 = the clipped point: an incident box corner (0-7), or
//           8 + 4 * edge + side, where the incident polygon's edge `edge` (0-11 an edge of the
//           incident box, 12-15 a stretch along reference side plane 0-3) crosses side `side`
//   kind 2  edge against edge: bits 0-3 = edge of A, bits 4-7 = edge of B
//   kind 3  a capsule's or cylinder's pair (collide_capsule.cpp, collide_convex.cpp): bits 0-7 =
//           the point (a capsule's end, a cylinder's rim point, a clipped point); bit 8 (9) set
//           where the point is on A's (B's) round surface, which stays where it is as the body
//           rolls, as a sphere's; bit 11 set where the normal is a face's (a box's or a
//           cylinder's flat face) and bit 12 whose (0 = A, 1 = B)
//
// Boxes number corners as box_corner() does, faces 2 * axis + (0 for +, 1 for -), and edges
// 4 * axis + the two other corner bits in order (the edge along `axis` through those corners).
namespace feature {
inline constexpr uint32_t corner(int index) { return uint32_t(index); }
inline constexpr uint32_t face_point(int reference_box, int reference_face, int point) {
  return (1u << 14) | (uint32_t(reference_box) << 12) | (uint32_t(reference_face) << 9) | uint32_t(point);
}
inline constexpr uint32_t clip_point(int edge, int side) { return uint32_t(8 + 4 * edge + side); }
inline constexpr uint32_t edge_pair(int edge_a, int edge_b) {
  return (2u << 14) | (uint32_t(edge_b) << 4) | uint32_t(edge_a);
}
inline constexpr uint32_t round_point(int point, bool round_a, bool round_b) {
  return (3u << 14) | (uint32_t(round_b) << 9) | (uint32_t(round_a) << 8) | uint32_t(point);
}
inline constexpr uint32_t on_face(int reference, int point, bool round_a, bool round_b) {
  return round_point(point, round_a, round_b) | (1u << 11) | (uint32_t(reference) << 12);
}
// Whether the point is on body `body`'s (0: A, 1: B) round surface: it does not move as that body turns.
inline constexpr bool round_of(uint32_t id, int body) { return (id >> 14) == 3 && (id >> (8 + body) & 1); }
// Kind 1's points and kind 3's against a face: the reference face, and its body.
inline constexpr bool against_face(uint32_t id) { return (id >> 14) == 1 || ((id >> 14) == 3 && (id >> 11 & 1)); }
// Whose corner the point is: 0 (A) or 1 (B) for an incident box's corner against a reference face,
// -1 for a point that both boxes make (crossing edges, an incident edge cut by a side plane) and
// for the single points of kind 0.
inline constexpr int corner_of(uint32_t id) {
  if ((id >> 14) == 3) return round_of(id, 0) ? 0 : round_of(id, 1) ? 1 : (id >> 11 & 1) ? int(1 - ((id >> 12) & 1)) : -1;
  return (id >> 14) == 1 && (id & 0x7f) < 8 ? int(1 - ((id >> 12) & 1)) : -1;
}
// Whose face the pair's normal is: 0 (A) or 1 (B) for a point against a reference face, -1 otherwise.
inline constexpr int face_of(uint32_t id) { return against_face(id) ? int((id >> 12) & 1) : -1; }
}  // namespace feature

// Keeps at most four of the contacts out[first..] (one pair's, sharing `normal`): the one
// farthest from `origin` along `search` (a unit direction across the normal, fixed in one of the
// bodies), the one farthest from it, then the two that add the most area, in their original
// order. A candidate displaces an earlier one only when clearly better, so that the choice does
// not flicker between steps. Returns how many are left.
int reduce_manifold(std::vector<Contact>& out, size_t first, const Vec3& normal, const Vec3& origin, const Vec3& search);

// A unit direction in the plane of the unit vectors u and v (u ⟂ v) at an angle that no box edge
// or diagonal takes (Box3D's numbers), for reduce_manifold's `search`: few ties along it.
inline Vec3 search_direction(const Vec3& u, const Vec3& v) { return 0.8912 * u - 0.4536 * v; }

}  // namespace impulse::physics
