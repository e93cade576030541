// The default method's contacts as the solver builds them each step (contact_prepare.cpp): one
// constraint per point, one per manifold (the points between one pair of bodies), its settings,
// and the materials' mixing rules. These are what the records, the bounces and the warm start
// read; the sweeps run on a packed copy with the rows of eq. 13 (contact_lanes.h).
#pragma once
#include "physics/math.h"

#include <cstdint>

namespace impulse::physics {

struct ContactSolverSettings {
  Real contact_hertz = 120;            // stiffness of the position correction, at most 1/5 of the
                                       // sub-step rate (see kMaxHertzPerSubstepRate)
  Real contact_damping_ratio = 10;
  Real max_push_velocity = 3;          // m/s, fastest the correction moves bodies apart
  Real restitution_threshold = 0.5;    // m/s, slower hits do not bounce (no resting jiggle)
  bool friction = true;                // tangential impulses on or off (exercise 1)
  Real rolling_resistance = 0;         // c: a sphere's contact resists rolling with a torque up to
                                       // c R N (R its radius, N the normal force); 0: a rigid ball
                                       // on a rigid plane rolls on for ever
};

// Contacts stiffer than this fraction of the sub-step rate are not stable. Box2D's rule is 1/4; at
// 1/4 a wall of boxes one box thick (the 210-box pyramid of ../shared/bench/SCENES.md) sways,
// growing over seconds, whatever the damping ratio, passes or solve order; friction feeds it
// (without friction it stays still). At 1/5, a pair's points solved together (pair_points.h),
// every pyramid measured stands still. The edge is a face's rocking: each row is soft by its own
// effective mass 1/K_ii, so a cube's four corners rock at 1.22 times the hertz (K's rocking
// eigenvalue is 1.5 K_ii), at a fifth 1/4.1 of the sub-step rate; at 1/4.5 the 210 pyramid sways.
constexpr Real kMaxHertzPerSubstepRate = Real(1) / 5;

constexpr int kMaxManifoldPoints = 4;  // the collision routines reduce every pair to four

// One contact point where the surfaces meet, at the step's start: each body's anchor (the point
// relative to its centre) and the separation along the normal less the anchors' part. Built from
// the narrow phase's contact by prepare(), kept in the lanes (contact_lanes.h) during the sub-steps.
struct ContactAnchors {
  Vec3 anchor_a = Vec3::Zero(), anchor_b = Vec3::Zero();
  Real adjusted_separation = 0;        // separation - dot(anchor_a - anchor_b, normal)
  uint32_t feature = 0;                // the contact's (manifold.h)
};

// One contact point's impulses, what the records, the loads and the next step's warm start read.
// Its anchors and rows are in the lanes; what its manifold's points share (the normal, the
// tangents, the materials) in the manifold.
struct ContactConstraint {
  uint32_t feature = 0;                // the contact's, to find it again next step
  Real normal_mass = 0;                // 1 / eq. 13's denominator, at the step's start
  // After prepare(): the warm start; during the sub-steps the packed lanes hold the current ones;
  // after store_impulses(): the last sub-step's, and the sums over the whole step for the records.
  Real normal_impulse = 0;
  Real total_normal_impulse = 0, total_tangent_impulse1 = 0, total_tangent_impulse2 = 0;
};

// The points between one pair of bodies, and their shared friction.
struct ManifoldConstraint {
  int a = -1, b = -1;                  // slots
  int first = 0, count = 0;            // its points in the constraint list
  // Its points', which share them (one pair, one normal).
  Vec3 normal = Vec3::Zero(), tangent1 = Vec3::Zero(), tangent2 = Vec3::Zero();
  Real friction = 0, restitution = 0;
  // The impulses, as for a point's: the warm start after prepare(), the lanes' during the
  // sub-steps, the last sub-step's and the step's totals after store_impulses().
  Real tangent_impulse1 = 0, tangent_impulse2 = 0, twist_impulse = 0;
  Real total_tangent_impulse1 = 0, total_tangent_impulse2 = 0;
  Real bounce_speed = 0;               // m/s, the speed the pair parts at after its hit
  // Each body's radius if it is a sphere, else 0; and whether its turning carries its contact
  // points with it: not a sphere's (its surface meets the other body where it is, however fast it
  // spins) nor a still body's.
  Real radius_a = 0, radius_b = 0;
  bool turns_a = true, turns_b = true;
  uint8_t hit_points = 0;              // bit i: point i bounced this step (contact_bounce.cpp)
};

// A manifold's load at the end of a step, for StackSink: its mean impulse a sub-step over the step
// (the step's total over its sub-steps: steadier than the last sub-step's) and the sum of its
// points' normal masses. Small and apart from the constraints, so that the thread that
// reads it does not pull in the lines of the constraints that another thread solves.
struct ManifoldLoad {
  int a = -1, b = -1;  // slots
  Real impulse = 0, normal_mass = 0;
  Vec3 normal = Vec3::UnitY();
};

}  // namespace impulse::physics
