#include "physics/shape.h"

#include <limits>

#include <cmath>
#include <numbers>
#include <string>

namespace impulse::physics {

Real shape_volume(const Shape& shape) {
  switch (shape.type) {
    // r·r·r, not std::pow: glibc chooses pow's code by the CPU (an FMA version where there is
    // FMA), and the physics must give the same bits on every x86-64 machine.
    case ShapeType::sphere: return Real(4) / 3 * std::numbers::pi * (shape.radius * shape.radius * shape.radius);
    case ShapeType::box: return 8 * shape.half_extents.prod();
    case ShapeType::plane: return 0;
  }
  return 0;
}

Mat3 shape_unit_inertia(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return Mat3::Identity() * (Real(2) / 5 * shape.radius * shape.radius);
    case ShapeType::box: {
      const Vec3 e2 = (2 * shape.half_extents).cwiseAbs2();
      return Vec3(e2.y() + e2.z(), e2.x() + e2.z(), e2.x() + e2.y()).asDiagonal() * (Real(1) / 12);
    }
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
    case ShapeType::plane: return Mat3::Zero();
  }
  return Mat3::Zero();
}

Real bounding_radius(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return shape.radius;
    case ShapeType::box: return shape.half_extents.norm();
    case ShapeType::plane: return 0;
  }
  return 0;
}

Real thinnest_half_size(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::sphere: return shape.radius;
    case ShapeType::box: return shape.half_extents.minCoeff();
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
    case ShapeType::plane:
      if (!is_finite(shape.normal) || shape.normal.norm() < Real(1e-9)) return "normal must be a non-zero finite vector";
      if (!std::isfinite(shape.offset)) return "offset must be finite";
      return {};
  }
  return "unknown shape";
}

}  // namespace impulse::physics
