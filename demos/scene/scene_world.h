// The scene's world, built from its bodies and joints: what the film steps and the tests probe.
#pragma once
#include "demos/scene/scene.h"
#include "physics/world.h"

#include <string>
#include <vector>

namespace impulse::demos {

physics::World build_world(const Scene& scene);

// What is odd but allowed at the start, as lines to print: bodies that overlap by more than a
// millimetre (the solver pushes them apart in the first steps, faster than they would ever move).
// Found without stepping a world.
std::vector<std::string> start_warnings(const Scene& scene);

}  // namespace impulse::demos
