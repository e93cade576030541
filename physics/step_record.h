// What one step did, as plain data for the renderer and for plots.
#pragma once
#include "physics/joint.h"
#include "physics/math.h"

#include <cstdint>
#include <vector>

namespace impulse::physics {

struct ContactRecord {
  int body_a = -1, body_b = -1;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitY();          // direction A is pushed (see Contact)
  Real penetration = 0;                 // m, at the start of the step
  Real normal_impulse = 0;              // N s over the step, along normal, on A (B gets the opposite)
  Vec3 tangent_impulse = Vec3::Zero();  // N s over the step, friction on A
};

struct JointRecord {
  JointType type = JointType::ball;
  int body_a = kWorld, body_b = kWorld;
  Vec3 anchor_a = Vec3::Zero(), anchor_b = Vec3::Zero();  // world points on A and on B
};

struct StepRecord {
  int64_t step = 0;
  Real time = 0;                        // s, at the end of the step
  std::vector<ContactRecord> contacts;  // touching, or pushed this step
  std::vector<JointRecord> joints;
  Real kinetic_energy = 0;              // J, linear and rotational
  Real potential_energy = 0;            // J, gravity, zero at the origin
  Vec3 linear_momentum = Vec3::Zero();  // kg m/s
  Vec3 angular_momentum = Vec3::Zero(); // kg m^2/s, about the origin
};

}  // namespace impulse::physics
