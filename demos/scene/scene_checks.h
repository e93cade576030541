// [[check]]: what a scene states must hold, checked as its world steps, so a course's CI guards
// the physics its captions claim. Each check is measured over its time window (from .. to, in
// simulated s) and compared with its bound:
//
//   kind = "momentum"     the total linear momentum changes by at most `tolerance` (kg m/s)
//   kind = "energy"       the total energy never rises above its value at `from` by more than
//                         `tolerance` times its size there (a share: 0.01 is 1 %)
//   kind = "at_rest"      `body` is slower than `speed` (m/s) at every step of the window
//   kind = "inside"       `body`'s centre is within `min` .. `max` (m) at the window's end
//   kind = "velocity"     `body`'s velocity is within `min` .. `max` (m/s) at the window's end
//   kind = "height"       `body`'s highest centre in the window is within `min` .. `max` (m), or,
//                         with `ratio`, that height over its starting height is `ratio` ± `tolerance`
//   kind = "drift"        `body` ends the window at most `distance` (m) from where it began it
//   kind = "penetration"  no contact's penetration exceeds `depth` (m)
//
// In a scene with [compare], `pane = N` makes a check about the Nth pane only (from 1).
#pragma once
#include <string>
#include <vector>

#include "physics/math.h"
#include "physics/world.h"

namespace impulse::demos {

struct CheckSpec {
  std::string kind;
  std::string text;       // how the scene states it, for reports: "[[check]] 2 (height of 'ball')"
  int body = -1;          // index into the scene's bodies, for the kinds that name one
  int pane = 0;           // in a comparison ([compare]), the pane (from 1) it is about; 0: every pane
  double from = 0, to = 1e9;
  double tolerance = 0, speed = 0, distance = 0, depth = 0, ratio = 0;
  physics::Vec3 min = physics::Vec3::Constant(-1e9), max = physics::Vec3::Constant(1e9);
};

struct CheckResult {
  std::string text;
  bool passed = false;
  std::string measured;  // "rose to 0.489 of its start (0.49 ± 0.02)"
};

// Watches a world step by step and measures every check.
class CheckWatch {
 public:
  explicit CheckWatch(std::vector<CheckSpec> checks);
  void start(const physics::World& world);  // before the first step
  void step(const physics::World& world);   // after each step
  std::vector<CheckResult> results() const;

 private:
  struct State {
    bool seen = false;      // the window began
    double start_value = 0; // momentum, energy, height or position at the window's start
    physics::Vec3 start_vector = physics::Vec3::Zero();
    double extreme = 0;     // largest change, energy rise, speed, height or depth in the window
    physics::Vec3 last = physics::Vec3::Zero();
  };
  void observe(const physics::World& world, double time, bool first);

  std::vector<CheckSpec> checks_;
  std::vector<State> states_;
};

}  // namespace impulse::demos
