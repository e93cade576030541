// A rigid body: what it is (shape, mass, material) and where it is (state).
#pragma once
#include "physics/planar.h"
#include "physics/shape.h"

#include <string>

namespace impulse::physics {

struct Material {
  Real restitution = 0.5;  // coefficient of restitution e, 0..1
  Real friction = 0.5;     // Coulomb coefficient mu, >= 0
  int kind = -1;           // which of the scene's named materials, for its pairs (materials.h); -1: none
};

// How a body's mass is spread: through its volume, or over its surface (a thin shell: a ping-pong
// ball, a hollow box).
enum class MassSpread { solid, hollow };

// What a scene asks for. Mass comes from `mass` when > 0, else from density x volume.
struct BodyDef {
  std::string name;
  Shape shape;
  bool is_static = false;  // infinite mass; planes and meshes are always static
  Real mass = 0;
  Real density = 1000;     // kg/m^3
  MassSpread spread = MassSpread::solid;  // the inertia's, from the shape (the mass stays `mass`'s)
  Vec3 principal_inertia = Vec3::Zero();  // kg m^2 about the body's own axes, in place of the shape's where set
  Material material;
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  int planar_axis = kNotPlanar;  // moves in the plane through `position` normal to this world axis
                                 // (0 x, 1 y, 2 z) and turns about it only (planar.h); static bodies ignore it
};

struct Body {
  std::string name;
  Shape shape;
  Material material;
  Real mass = 0;       // 0 for static bodies
  Real inv_mass = 0;
  Mat3 inertia_local = Mat3::Zero();
  Mat3 inv_inertia_local = Mat3::Zero();
  Mat3 inv_inertia_world = Mat3::Zero();  // R I^-1 R^T, refreshed every step (planar: the lock's, planar.h)
  int planar_axis = kNotPlanar;           // a moving body's lock (BodyDef::planar_axis)

  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();

  bool awake = true;       // false while sleeping (at rest, not simulated until touched)
  Real sleep_time = 0;     // s spent slower than the sleep tolerances

  bool is_static() const { return inv_mass == 0; }
  void refresh_world_inertia() {
    if (planar_axis != kNotPlanar) {
      inv_inertia_world = planar_inverse_inertia(inertia_world(), planar_axis);
      return;
    }
    const Mat3 r = orientation.toRotationMatrix();
    inv_inertia_world = r * inv_inertia_local * r.transpose();
  }
  Mat3 inertia_world() const {
    const Mat3 r = orientation.toRotationMatrix();
    return r * inertia_local * r.transpose();
  }
};

// Builds a body from its definition. Throws std::invalid_argument with the reason for an
// impossible definition (zero radius, negative mass, non-finite position, ...).
Body make_body(const BodyDef& def);

}  // namespace impulse::physics
