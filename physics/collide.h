// Narrow phase: the contact points between two bodies' shapes.
#pragma once
#include "physics/body.h"
#include "physics/contact.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

// The face a box pair's manifold was built on, kept from step to step (Box3D's SAT cache, faces
// only): while that face still gives touching points whose deepest moved less than a slop, it is
// used again, so that the reference face does not flip between two boxes' nearly parallel faces
// as they rock (each flip moves every point, and rocks them on).
struct SatCache {
  int8_t reference = -1;  // -1 none, 0 a face of A, 1 a face of B
  int8_t axis = 0;        // that box's axis, 0-2
  int8_t sign = 0;        // which of its two faces: +1 or -1
  float deepest = 0;      // m, the deepest clipped point's separation when it was built
};

// Appends to `out` the contacts between bodies a and b (indices ia, ib) whose separation is below
// `margin` (a positive margin yields speculative contacts). The appended contacts may have A and B
// swapped so that A is the first shape in ShapeType's order. Returns how many it added.
// Feature ids are laid out in manifold.h. `cache`, if given, is the pair's SatCache, read and
// updated (box pairs use it).
int collide(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out,
            SatCache* cache = nullptr);

// The pair functions collide() dispatches to, A and B already in that order. Same contract.
int collide_spheres(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_box(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_boxes(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out,
                  SatCache* cache = nullptr);
int collide_box_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_capsule(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_cylinder(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_capsule_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_cylinder_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_hull(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_hull_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
// A box, capsule, cylinder or hull against a capsule, cylinder or hull: GJK and EPA, then clipping
// (collide_convex.cpp).
int collide_convex(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
// A sphere, and any other shape but a plane, against a static mesh (collide_mesh.cpp).
int collide_sphere_mesh(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_convex_mesh(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);

}  // namespace impulse::physics
