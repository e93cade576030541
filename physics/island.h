// Sleeping: bodies that have rested long enough, together with everything they touch (their
// island), stop being simulated until an awake body reaches them.
#pragma once
#include "physics/body.h"
#include "physics/contact.h"

#include <utility>
#include <vector>

namespace impulse::physics {

struct SleepSettings {
  bool enabled = true;
  Real velocity_tolerance = 0.05;  // m/s, for the fastest point of the body (Box2D's b2_linearSleepTolerance)
  Real time_to_sleep = 0.5;        // s below the tolerance before an island sleeps
};

class Islands {
 public:
  // After a step: advances each body's sleep timer and puts to sleep every island (bodies joined
  // by touching contacts or by `links`, e.g. joints) whose bodies have all rested for
  // time_to_sleep, and that something holds: a touching contact with friction (`friction` on, both
  // materials' mu > 0) against a static or sleeping body, or a joint to the world or a static body
  // (`anchored`: the bodies jointed so). An island nothing holds sleeps only when it is exactly
  // still: a drift in zero gravity, a ball on a frictionless floor move on as slowly as they move
  // (Newton's first law). A sleeping body's velocities are zeroed.
  void update(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
              const std::vector<std::pair<int, int>>& links, const std::vector<int>& anchored, bool friction,
              Real touching_distance, Real dt, const SleepSettings& settings);

  // Wakes the island of every sleeping body that a link joins to an awake body, or that an awake
  // body touches (a contact closer than touching_distance) or closes on faster than the sleep
  // tolerance. Returns whether any woke (their mutual contacts then need finding again).
  bool wake_touched(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                    const std::vector<std::pair<int, int>>& links, Real touching_distance,
                    const SleepSettings& settings);

 private:
  int find(int i);
  void join(int a, int b);
  void wake_island(std::vector<Body>& bodies, int island);

  std::vector<int> parent_;      // union-find forest, rebuilt each update
  std::vector<int> island_of_;   // the island a sleeping body fell asleep in, -1 when awake
};

}  // namespace impulse::physics
