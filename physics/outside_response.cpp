// The workshop page's seam, outside: a contact's two bodies as listing 1's RigidBody in floats,
// handed to the world's outside response, and what it did read back (outside_response.h).
#include "physics/outside_response.h"

#include "physics/world.h"

#include <cstdio>
#include <tuple>

namespace impulse::physics {

namespace {

std::array<float, 3> floats(const Vec3& v) { return {float(v.x()), float(v.y()), float(v.z())}; }
Vec3 vec(const std::array<float, 3>& v) { return Vec3(v[0], v[1], v[2]); }
std::array<float, 9> floats(const Mat3& m) {
  std::array<float, 9> out;
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column) out[3 * row + column] = float(m(row, column));
  return out;
}

// The listing's body from the solver's view of it (`view`) and the body itself (what the view
// does not carry: its orientation, its inertia in its own frame, its mass for m_forces). A body
// the solver holds still (static, asleep) shows as the listing's immovable one: no inverse mass,
// no inverse inertia.
PlainBody plain_body(const Body& body, const RigidBody& view, const Vec3& gravity, const ContactMaterial& material) {
  PlainBody plain;
  plain.centre = floats(view.centre);
  plain.inv_mass = float(view.inv_mass);
  plain.lin_velocity = floats(view.lin_velocity);
  plain.ang_velocity = floats(view.ang_velocity);
  plain.forces = floats(view.inv_mass > 0 ? Vec3(body.mass * gravity) : Vec3::Zero());
  plain.inv_inertia = floats(view.inv_mass > 0 ? body.inv_inertia_local : Mat3::Zero());
  plain.world_inv_inertia = floats(view.world_inv_inertia);
  plain.orientation = {float(body.orientation.w()), float(body.orientation.x()), float(body.orientation.y()),
                       float(body.orientation.z())};
  plain.restitution = float(material.restitution);
  plain.friction = float(material.friction);
  return plain;
}

std::string describe_vector(const std::array<float, 3>& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", v[0], v[1], v[2]);
  return text;
}

}  // namespace

// One call of the outside response for one contact. The bodies' new velocities are kept (a body
// that does not move keeps its own, whatever the function wrote), and the impulse it applied is
// read from the momentum it gave: on a, m_a dv_a; or, when a does not move, -m_b dv_b (eq. 2:
// an impulse is a change of momentum). Split along the normal and tangent_basis(normal), it is
// recorded as the page's is.
World::TeachingImpulse World::respond_outside(const Contact& contact, RigidBody& a, RigidBody& b, Real penetration) {
  const ContactMaterial material = contact_material(contact.body_a, contact.body_b);
  PlainBody plain_a = plain_body(bodies_[contact.body_a], a, settings_.gravity, material);
  PlainBody plain_b = plain_body(bodies_[contact.body_b], b, settings_.gravity, material);
  const PlainBody sent_a = plain_a, sent_b = plain_b;
  const PlainContact plain_contact{floats(contact.point), floats(contact.normal), float(penetration), float(settings_.time_step)};
  try {
    response_->respond(plain_a, plain_b, plain_contact);
    for (const PlainBody* body : {&plain_a, &plain_b})
      for (const auto* v : {&body->lin_velocity, &body->ang_velocity})
        if (!is_finite(vec(*v)))
          throw ResponseFailure("it left a velocity that is not a number: " + describe_vector(*v));
  } catch (const ResponseFailure& failure) {
    char when[64];
    std::snprintf(when, sizeof when, "step %lld (t = %.4f s)", static_cast<long long>(step_count_ + 1), time_ + settings_.time_step);
    throw ResponseFailure(std::string(failure.what()) + "; at " + when + ", the contact of '" + bodies_[contact.body_a].name +
                          "' and '" + bodies_[contact.body_b].name + "'");
  }

  // What the function changed, in its floats, added to the world's own doubles: a velocity it did
  // not touch stays exactly as it was, and so does the record of an impulse it did not apply.
  auto change = [](const std::array<float, 3>& now, const std::array<float, 3>& sent) -> Vec3 { return vec(now) - vec(sent); };
  Vec3 impulse = Vec3::Zero();
  if (a.inv_mass > 0)
    impulse = change(plain_a.lin_velocity, sent_a.lin_velocity) / a.inv_mass;
  else if (b.inv_mass > 0)
    impulse = -change(plain_b.lin_velocity, sent_b.lin_velocity) / b.inv_mass;
  for (auto [view, plain, sent] : {std::tuple<RigidBody*, const PlainBody*, const PlainBody*>{&a, &plain_a, &sent_a}, {&b, &plain_b, &sent_b}}) {
    if (view->inv_mass == 0) continue;
    view->lin_velocity += change(plain->lin_velocity, sent->lin_velocity);
    view->ang_velocity += change(plain->ang_velocity, sent->ang_velocity);
  }
  Vec3 t1, t2;
  tangent_basis(contact.normal, t1, t2);
  return {impulse.dot(contact.normal), impulse.dot(t1), impulse.dot(t2)};
}

}  // namespace impulse::physics
