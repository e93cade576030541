// The scene's world, built from its bodies and joints: what the film steps and the tests probe.
#pragma once
#include "demos/scene/scene_file.h"
#include "physics/world.h"

namespace impulse::demos {

physics::World build_world(const Scene& scene);

}  // namespace impulse::demos
