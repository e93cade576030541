// How the world answers its contacts, by the scene's method (response_method.h). The default
// (`impulse`) runs the soft step's stages (soft_step.h); the teaching methods call their page
// (workshop_listing.h, projection_method.h, penalty_method.h) once per contact with a plain
// contact: the two bodies as listing 1's RigidBody, the point, the normal and the penetration now.
#include "physics/listing_reference.h"
#include "physics/normal_impulse.h"
#include "physics/penalty_method.h"
#include "physics/projection_method.h"
#include "physics/workshop_listing.h"
#include "physics/world.h"

namespace impulse::physics {

// The step's response, by the scene's method: the default's sub-steps, or a teaching page's.
void World::respond(Real dt, Real h) {
  switch (settings_.method) {
    case ResponseMethod::impulse: solve_impulse(h); break;
    case ResponseMethod::workshop: solve_workshop(dt); break;
    case ResponseMethod::projection: solve_projection(dt); break;
    case ResponseMethod::penalty: solve_penalty(h); break;
  }
}

// Box2D v3's soft step: the stages of soft_step.h, sub-step after sub-step, joints among them.
void World::solve_impulse(Real h) {
  for (int i = 0; i < substeps_; ++i)
    soft_step_.substep(contact_solver_, joints_.empty() ? nullptr : &joint_solver_, solver_bodies_, h,
                       [&](int slot) { integrate_velocity(solver_bodies_.states[slot], solver_bodies_.inertia[slot], h); },
                       [&](int slot) { integrate_position(solver_bodies_.states[slot], solver_bodies_.inertia[slot], h); });
  contact_solver_.store_impulses();
}

// page(contact, a, b, penetration) for every contact, in the sweeps' order (the default method's;
// any fixed order would do, and this one keeps the results these methods have always given),
// with its bodies as listing 1 sees them, then their new velocities and displacement kept.
template <class Page>
void World::for_each_plain_contact(Page&& page) {
  const std::vector<int>& slots = contact_solver_.slots();
  contact_solver_.for_each_contact_in_sweep_order([&](int i) {
    const Contact& contact = contacts_[i];
    const int slot_a = slots[contact.body_a], slot_b = slots[contact.body_b];
    BodyState& sa = solver_bodies_.states[slot_a];
    BodyState& sb = solver_bodies_.states[slot_b];
    RigidBody a{bodies_[contact.body_a].position, sa.inv_mass, solver_bodies_.inertia[slot_a].inv_inertia, sa.v, sa.w, sa.dp};
    RigidBody b{bodies_[contact.body_b].position, sb.inv_mass, solver_bodies_.inertia[slot_b].inv_inertia, sb.v, sb.w, sb.dp};
    const Vec3 ra = contact.point - a.centre, rb = contact.point - b.centre;
    // A sphere's surface meets the other body where it is, however the sphere turns.
    const bool turns_a = bodies_[contact.body_a].shape.type != ShapeType::sphere, turns_b = bodies_[contact.body_b].shape.type != ShapeType::sphere;
    const Real penetration = -separation_now(contact.normal, ra, rb, contact.separation - (ra - rb).dot(contact.normal), sa, turns_a, sb, turns_b);
    page(contact, a, b, penetration, teaching_impulses_[i]);
    for (auto [s, body] : {std::pair<BodyState*, const RigidBody*>{&sa, &a}, {&sb, &b}}) {
      s->v = body->lin_velocity;
      s->w = body->ang_velocity;
      s->dp = body->displacement;
    }
  });
}

// Listing 1: respond to the contacts found at the start of the step, then move (one full step).
void World::solve_workshop(Real dt) {
  for_each_plain_contact([&](const Contact& contact, RigidBody& a, RigidBody& b, Real penetration, TeachingImpulse& total) {
    if (penetration < 0) return;  // the listing only sees intersecting pairs
    if (response_) {              // a student's own AddCollisionImpulse (outside_response.h)
      const TeachingImpulse applied = respond_outside(contact, a, b, penetration);
      total.normal += applied.normal;
      total.tangent1 += applied.tangent1;
      total.tangent2 += applied.tangent2;
      return;
    }
    const ContactMaterial material = contact_material(contact.body_a, contact.body_b);
    const ListingOptions options{material.restitution, settings_.contact.friction, settings_.printed_eq8_sign};
    const ListingImpulse applied =
        settings_.reference_listing
            ? reference_collision_impulse(a, b, contact.point, contact.normal, penetration, {material.restitution, material.friction, dt})
            : add_collision_impulse(a, b, contact.point, contact.normal, penetration, options);
    total.normal += applied.normal;
    if (applied.tangent_direction.isZero(0)) return;
    Vec3 t1, t2;
    tangent_basis(contact.normal, t1, t2);
    total.tangent1 += applied.tangent * applied.tangent_direction.dot(t1);
    total.tangent2 += applied.tangent * applied.tangent_direction.dot(t2);
  });
  move_bodies(dt);
}

// Move, then push overlapping bodies apart. Velocities keep what gravity gave them.
void World::solve_projection(Real dt) {
  move_bodies(dt);
  for_each_plain_contact([&](const Contact& contact, RigidBody& a, RigidBody& b, Real penetration, TeachingImpulse&) {
    project_apart(a, b, contact.normal, penetration);
  });
}

// Semi-implicit Euler per sub-step: forces from the sub-step's starting state, then velocities,
// then positions.
void World::solve_penalty(Real h) {
  for (int i = 0; i < substeps_; ++i) {
    for_each_plain_contact([&](const Contact& contact, RigidBody& a, RigidBody& b, Real penetration, TeachingImpulse& total) {
      const Real friction = contact_material(contact.body_a, contact.body_b).friction;
      const PenaltyImpulse applied = apply_penalty_impulse(a, b, contact.point, contact.normal, penetration, friction, settings_.penalty, h);
      total.normal += applied.normal;
      total.tangent1 += applied.tangent1;
      total.tangent2 += applied.tangent2;
    });
    move_bodies(h);
  }
}

// The teaching methods' motion over h: gravity, the joints (solved as in the default method, with
// and then without their position bias), and the positions. Contacts are the pages' alone.
void World::move_bodies(Real h) {
  integrate_velocities(h);
  solve_joints(h, true);
  integrate_positions(h);
  solve_joints(h, false);
}

void World::solve_joints(Real h, bool use_bias) {
  if (joints_.empty()) return;
  if (use_bias) joint_solver_.warm_start(solver_bodies_);
  joint_solver_.solve(solver_bodies_, 1 / h, use_bias);
}

}  // namespace impulse::physics
