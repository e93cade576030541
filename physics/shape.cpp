#include "physics/shape.h"

#include <limits>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace impulse::physics {

const char* shape_name(ShapeType type) {
  switch (type) {
    case ShapeType::sphere: return "sphere";
    case ShapeType::box: return "box";
    case ShapeType::capsule: return "capsule";
    case ShapeType::cylinder: return "cylinder";
    case ShapeType::hull: return "hull";
    case ShapeType::mesh: return "mesh";
    case ShapeType::plane: return "plane";
  }
  return "shape";
}

Real shape_volume(const Shape& shape) {
  switch (shape.type) {
    // r·r·r, not std::pow: glibc chooses pow's code by the CPU (an FMA version where there is
    // FMA), and the physics must give the same bits on every x86-64 machine.
    case ShapeType::sphere: return Real(4) / 3 * std::numbers::pi * (shape.radius * shape.radius * shape.radius);
    case ShapeType::box: return 8 * shape.half_extents.prod();
    case ShapeType::capsule:
      return std::numbers::pi * shape.radius * shape.radius * (2 * shape.half_height + Real(4) / 3 * shape.radius);
    case ShapeType::cylinder: return std::numbers::pi * shape.radius * shape.radius * (2 * shape.half_height);
    case ShapeType::hull: return shape.hull()->volume;
    case ShapeType::mesh:
    case ShapeType::plane: return 0;
  }
  return 0;
}

namespace {

// Moments about the axis (y) and across it (x, z) of mass `axial` and `across`, as a diagonal.
Mat3 about_y(Real axial, Real across) { return Vec3(across, axial, across).asDiagonal(); }

// A capsule per unit mass: the cylinder between the caps (mass m_c = pi r^2 2h) and the two
// half-balls together (m_s = 4/3 pi r^3), each cap's inertia moved to the centre by parallel axes
// (its centre of mass c from its flat face, at h + c from the capsule's centre):
//   solid (c = 3r/8):  I_y = m_c r^2/2 + m_s 2r^2/5,  I_x = m_c (r^2/4 + h^2/3) + m_s (2r^2/5 + h^2 + 3hr/4)
//   shell (c = r/2, areas for masses: a_c = 2 pi r 2h, a_s = 4 pi r^2):
//                      I_y = a_c r^2 + a_s 2r^2/3,    I_x = a_c (r^2/2 + h^2/3) + a_s (2r^2/3 + h^2 + hr)
Mat3 capsule_unit_inertia(Real r, Real h, bool shell) {
  const Real r2 = r * r, h2 = h * h;
  const Real side = shell ? 2 * std::numbers::pi * r * 2 * h : std::numbers::pi * r2 * 2 * h;
  const Real caps = shell ? 4 * std::numbers::pi * r2 : Real(4) / 3 * std::numbers::pi * r2 * r;
  const Real axial = shell ? side * r2 + caps * (Real(2) / 3 * r2) : side * r2 / 2 + caps * (Real(2) / 5 * r2);
  const Real across = shell ? side * (r2 / 2 + h2 / 3) + caps * (Real(2) / 3 * r2 + h2 + h * r)
                            : side * (r2 / 4 + h2 / 3) + caps * (Real(2) / 5 * r2 + h2 + Real(3) / 4 * h * r);
  return about_y(axial, across) / (side + caps);
}

}  // namespace

Mat3 shape_unit_inertia(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return Mat3::Identity() * (Real(2) / 5 * shape.radius * shape.radius);
    case ShapeType::box: {
      const Vec3 e2 = (2 * shape.half_extents).cwiseAbs2();
      return Vec3(e2.y() + e2.z(), e2.x() + e2.z(), e2.x() + e2.y()).asDiagonal() * (Real(1) / 12);
    }
    case ShapeType::capsule: return capsule_unit_inertia(shape.radius, shape.half_height, false);
    case ShapeType::cylinder: {  // r^2/2 about the axis, (3 r^2 + (2h)^2) / 12 across it
      const Real r2 = shape.radius * shape.radius, h2 = shape.half_height * shape.half_height;
      return about_y(r2 / 2, r2 / 4 + h2 / 3);
    }
    case ShapeType::hull: return shape.hull()->unit_inertia;
    case ShapeType::mesh:
    case ShapeType::plane: return Mat3::Zero();
  }
  return Mat3::Zero();
}

Mat3 shape_unit_shell_inertia(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return Mat3::Identity() * (Real(2) / 3 * shape.radius * shape.radius);
    case ShapeType::box: {
      // A face of half sizes u, v at distance d from the centre: about its normal (u^2 + v^2) / 3,
      // about its side along v, v^2 / 3 + d^2 (parallel axes). The pair of faces across axis k
      // carries the share (half sizes of the other two multiplied) / (the sum over the three pairs).
      const Vec3 h = shape.half_extents, e2 = h.cwiseProduct(h);
      const Vec3 share = Vec3(h.y() * h.z(), h.x() * h.z(), h.x() * h.y()) / (h.y() * h.z() + h.x() * h.z() + h.x() * h.y());
      Vec3 moments = Vec3::Zero();
      for (int axis = 0; axis < 3; ++axis)
        for (int face = 0; face < 3; ++face) {
          if (face == axis) {
            moments[axis] += share[face] * (e2.sum() - e2[face]) / 3;
          } else {
            const int other = 3 - axis - face;  // the plate spans this axis across `axis`
            moments[axis] += share[face] * (e2[other] / 3 + e2[face]);
          }
        }
      return moments.asDiagonal();
    }
    case ShapeType::capsule: return capsule_unit_inertia(shape.radius, shape.half_height, true);
    case ShapeType::cylinder: {  // the side alone, a tube: r^2 about the axis, r^2/2 + (2h)^2/12 across it
      const Real r2 = shape.radius * shape.radius, h2 = shape.half_height * shape.half_height;
      return about_y(r2, r2 / 2 + h2 / 3);
    }
    case ShapeType::hull: return shape.hull()->unit_shell_inertia;
    case ShapeType::mesh:
    case ShapeType::plane: return Mat3::Zero();
  }
  return Mat3::Zero();
}

Real reach_along(const Shape& shape, const Quat& orientation, const Vec3& d) {
  const Vec3 local = rotate(orientation.conjugate(), d);
  const Real along = std::abs(local.y()), across = std::sqrt(std::max(Real(1) - along * along, Real(0)));
  switch (shape.type) {
    case ShapeType::sphere: return shape.radius;
    case ShapeType::box: return local.cwiseAbs().dot(shape.half_extents);
    case ShapeType::capsule: return shape.half_height * along + shape.radius;
    case ShapeType::cylinder: return shape.half_height * along + shape.radius * across;
    case ShapeType::hull: {
      Real reach = -std::numeric_limits<Real>::infinity();
      for (const Vec3& p : shape.hull()->corners) reach = std::max(reach, p.dot(local));
      return reach;
    }
    case ShapeType::mesh: {
      Real reach = -std::numeric_limits<Real>::infinity();
      for (const Vec3& p : shape.mesh()->vertices) reach = std::max(reach, p.dot(local));
      return reach;
    }
    case ShapeType::plane: return 0;
  }
  return 0;
}

Real bounding_radius(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return shape.radius;
    case ShapeType::box: return shape.half_extents.norm();
    case ShapeType::capsule: return shape.half_height + shape.radius;
    case ShapeType::cylinder: return std::sqrt(shape.radius * shape.radius + shape.half_height * shape.half_height);
    case ShapeType::hull: {
      Real farthest = 0;
      for (const Vec3& p : shape.hull()->corners) farthest = std::max(farthest, p.norm());
      return farthest;
    }
    case ShapeType::mesh: {
      Real farthest = 0;
      for (const Vec3& p : shape.mesh()->vertices) farthest = std::max(farthest, p.norm());
      return farthest;
    }
    case ShapeType::plane: return 0;
  }
  return 0;
}

Real thinnest_half_size(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return shape.radius;
    case ShapeType::box: return shape.half_extents.minCoeff();
    case ShapeType::capsule: return shape.radius;
    case ShapeType::cylinder: return std::min(shape.radius, shape.half_height);
    case ShapeType::hull: {  // the nearest face from the centre
      Real nearest = std::numeric_limits<Real>::infinity();
      for (const HullFace& face : shape.hull()->faces) nearest = std::min(nearest, face.offset);
      return nearest;
    }
    case ShapeType::mesh:
    case ShapeType::plane: return std::numeric_limits<Real>::infinity();
  }
  return 0;
}

std::string shape_problem(const Shape& shape) {
  auto num = [](Real v) { return std::to_string(v); };
  switch (shape.type) {
    case ShapeType::sphere:
      if (!(shape.radius > 0) || !std::isfinite(shape.radius)) return "radius must be a finite number > 0, got " + num(shape.radius);
      return {};
    case ShapeType::box:
      if (!(shape.half_extents.minCoeff() > 0) || !is_finite(shape.half_extents))
        return "half_extents must all be finite and > 0";
      return {};
    case ShapeType::capsule:
    case ShapeType::cylinder:
      if (!(shape.radius > 0) || !std::isfinite(shape.radius)) return "radius must be a finite number > 0, got " + num(shape.radius);
      if (!(shape.half_height > 0) || !std::isfinite(shape.half_height))
        return "height must be a finite number > 0, got " + num(2 * shape.half_height);
      return {};
    case ShapeType::hull:
      if (!shape.hull() || shape.hull()->faces.size() < 4 || !(shape.hull()->volume > 0)) return "a hull must enclose a volume";
      return {};
    case ShapeType::mesh:
      if (!shape.mesh() || shape.mesh()->triangles.empty()) return "a mesh needs at least one triangle";
      return {};
    case ShapeType::plane:
      if (!is_finite(shape.normal) || shape.normal.norm() < Real(1e-9)) return "normal must be a non-zero finite vector";
      if (!std::isfinite(shape.offset)) return "offset must be finite";
      return {};
  }
  return "unknown shape";
}

}  // namespace impulse::physics
