// Narrow phase: the contact points between two bodies' shapes.
#pragma once
#include "physics/body.h"
#include "physics/contact.h"

#include <vector>

namespace impulse::physics {

// Appends to `out` the contacts between bodies a and b (indices ia, ib) whose separation is below
// `margin` (a positive margin yields speculative contacts). The appended contacts may have A and B
// swapped so that A is the first shape in the order sphere, box, plane. Returns how many it added.
// Feature ids are laid out in manifold.h.
int collide(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);

// The pair functions collide() dispatches to, A and B already in that order. Same contract.
int collide_spheres(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_box(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_sphere_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_boxes(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);
int collide_box_plane(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out);

}  // namespace impulse::physics
