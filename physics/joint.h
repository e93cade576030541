// Impulse joints (the workshop's advanced exercise): constraints that join two bodies, or a body
// to the world.
#pragma once
#include "physics/math.h"

#include <string>

namespace impulse::physics {

enum class JointType {
  ball,      // ball and socket: one shared point, free rotation
  hinge,     // a shared point and a shared axis: rotation about the axis only
  distance,  // a rod (fixed length) or a rope (at most the length) between two points
};

constexpr int kWorld = -1;  // body index meaning "fixed in the world"

// In world space, at the bodies' current poses.
struct JointDef {
  std::string name;
  JointType type = JointType::ball;
  int body_a = kWorld, body_b = kWorld;
  Vec3 anchor = Vec3::Zero();     // ball, hinge: the shared point
  Vec3 axis = Vec3::UnitZ();      // hinge
  Vec3 anchor_a = Vec3::Zero();   // distance: the point on A ...
  Vec3 anchor_b = Vec3::Zero();   // ... and on B
  Real length = 0;                // distance: <= 0 means the current distance
  bool rope = false;              // distance: may go slack
};

// A joint's accumulated impulses.
struct JointImpulse {
  Vec3 linear = Vec3::Zero();  // ball, hinge: on B (A gets the opposite)
  Real angular[2] = {0, 0};    // hinge: about the two directions across the axis
  Real axial = 0;              // distance: along A->B, on B
};

struct Joint {
  std::string name;
  JointType type = JointType::ball;
  int body_a = kWorld, body_b = kWorld;
  Vec3 local_anchor_a = Vec3::Zero(), local_anchor_b = Vec3::Zero();  // in each body's frame
  Vec3 local_axis_a = Vec3::UnitZ(), local_axis_b = Vec3::UnitZ();    // hinge
  Real length = 0;
  bool rope = false;
  JointImpulse impulse;  // accumulated, warm started from step to step
};

}  // namespace impulse::physics
