// A response written outside the engine: a student's AddCollisionImpulse (listing 1), run in
// place of the workshop method's own page (workshop_listing.h). The world hands it what the page
// gets, as plain floats (the listing's types): two bodies and one touching contact, once per
// contact per step, in the order the page is called. It reads back the two velocities, and takes
// the impulse it applied to be the change of the bodies' momentum, so that the records (and the
// film's arrows and labels) show it as they show the page's.
//
// How the function is run (a compiled file, in a child process with a time limit) is the
// caller's: demos/response/. The physics only knows this seam.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace impulse::physics {

// Listing 1's RigidBody (lines 3-23), as the world fills it in at each call.
struct PlainBody {
  std::array<float, 3> centre{};             // m_centre: the centre of mass, where the step began
  float inv_mass = 0;                        // m_invMass; 0: does not move (static or asleep)
  std::array<float, 3> lin_velocity{};       // m_linVelocity
  std::array<float, 3> forces{};             // m_forces: gravity's m g (nothing else pushes)
  std::array<float, 9> inv_inertia{};        // m_invInertia: body frame, row by row
  std::array<float, 3> ang_velocity{};       // m_angVelocity, world frame
  std::array<float, 4> orientation{1, 0, 0, 0};  // m_orientation: w, x, y, z (body to world)
  std::array<float, 3> torques{};            // m_torques: none
  std::array<float, 9> world_inv_inertia{};  // m_worldInvInertia = R I^-1 R^T, row by row
  float restitution = 0;                     // the pair's e (materials.h), for m_restitution
  float friction = 0;                        // the pair's mu, for m_friction; 0 with friction off
};

// The contact as the listing's arguments: hitPoint, normal (the direction body a is pushed) and
// penetration (> 0 inside), and the step the call belongs to.
struct PlainContact {
  std::array<float, 3> point{};
  std::array<float, 3> normal{};
  float penetration = 0;
  float time_step = 0;  // s, for TimeStep()
};

class OutsideResponse {
 public:
  virtual ~OutsideResponse() = default;
  // Changes a's and b's velocities as AddCollisionImpulse(a, b, point, normal, penetration) does.
  // Throws ResponseFailure when the function cannot answer (it crashed, looped, made a NaN).
  virtual void respond(PlainBody& a, PlainBody& b, const PlainContact& contact) = 0;
};

// What went wrong in an outside response, in words for its author ("... crashed: SIGSEGV").
class ResponseFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Makes a response for one world: each world calls its own, so worlds stepped at once on
// different threads never share one (a child process is not shared). Empty: none.
using OutsideResponseMaker = std::function<std::unique_ptr<OutsideResponse>()>;

}  // namespace impulse::physics
