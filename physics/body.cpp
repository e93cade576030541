#include "physics/body.h"

#include <cmath>
#include <stdexcept>

namespace impulse::physics {

namespace {
void require(bool ok, const std::string& why) {
  if (!ok) throw std::invalid_argument(why);
}
}  // namespace

Body make_body(const BodyDef& def) {
  const std::string problem = shape_problem(def.shape);
  require(problem.empty(), problem);
  require(std::isfinite(def.mass) && def.mass >= 0, "mass must be >= 0 (0 means: from density), got " + std::to_string(def.mass));
  require(std::isfinite(def.density) && def.density > 0, "density must be > 0, got " + std::to_string(def.density));
  require(def.material.restitution >= 0 && def.material.restitution <= 1,
          "restitution must be between 0 and 1, got " + std::to_string(def.material.restitution));
  require(def.material.friction >= 0 && std::isfinite(def.material.friction),
          "friction must be >= 0, got " + std::to_string(def.material.friction));
  require(is_finite(def.position) && is_finite(def.velocity) && is_finite(def.angular_velocity),
          "position, velocity and angular velocity must be finite");
  require(is_finite(def.orientation) && def.orientation.norm() > Real(1e-9), "orientation must be a non-zero quaternion");
  require(def.principal_inertia.isZero() ||
              (is_finite(def.principal_inertia) && def.principal_inertia.minCoeff() > 0 &&
               2 * def.principal_inertia.maxCoeff() <= def.principal_inertia.sum() * (1 + Real(1e-12))),
          "principal_inertia must be three moments > 0, none larger than the other two together (a rigid body's), got [" +
              std::to_string(def.principal_inertia.x()) + ", " + std::to_string(def.principal_inertia.y()) + ", " +
              std::to_string(def.principal_inertia.z()) + "]");
  require(def.planar_axis >= kNotPlanar && def.planar_axis <= 2,
          "planar_axis must be 0, 1 or 2 (x, y, z) or kNotPlanar, got " + std::to_string(def.planar_axis));

  Body body;
  body.name = def.name;
  body.shape = def.shape;
  body.material = def.material;
  body.position = def.position;
  body.orientation = def.orientation.normalized();
  if (def.shape.type == ShapeType::plane) body.shape.normal.normalize();

  if (!def.is_static && def.shape.type != ShapeType::plane && def.shape.type != ShapeType::mesh) {
    body.mass = def.mass > 0 ? def.mass : def.density * shape_volume(def.shape);
    body.inv_mass = 1 / body.mass;
    body.inertia_local = !def.principal_inertia.isZero()          ? Mat3(def.principal_inertia.asDiagonal())
                         : def.spread == MassSpread::hollow ? body.mass * shape_unit_shell_inertia(def.shape)
                                                            : body.mass * shape_unit_inertia(def.shape);
    body.inv_inertia_local = body.inertia_local.inverse();
    body.velocity = def.velocity;
    body.angular_velocity = def.angular_velocity;
    body.planar_axis = def.planar_axis;
    hold_in_plane(body.velocity, body.angular_velocity, body.planar_axis);  // what the lock allows, from the start
  }
  body.refresh_world_inertia();
  return body;
}

}  // namespace impulse::physics
