#include "demos/scene/scene_world.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace impulse::demos {

physics::World build_world(const Scene& scene) {
  physics::World world(scene.world);
  for (const physics::BodyDef& def : scene.bodies) world.add_body(def);
  for (const physics::JointDef& def : scene.joints) world.add_joint(def);  // by index into bodies
  return world;
}

std::vector<std::string> start_warnings(const Scene& scene) {
  constexpr double kOverlap = 1e-3;  // m
  physics::World world = build_world(scene);
  world.step();
  std::map<std::pair<int, int>, double> deepest;  // per pair of bodies
  for (const physics::ContactRecord& contact : world.record().contacts)
    if (contact.penetration > kOverlap) {
      double& depth = deepest[{contact.body_a, contact.body_b}];
      depth = std::max(depth, double(contact.penetration));
    }
  auto name = [&](int body) { return body >= 0 ? "'" + scene.bodies[body].name + "'" : std::string("the world"); };
  std::vector<std::string> warnings;
  for (const auto& [pair, depth] : deepest) {
    char metres[32];
    std::snprintf(metres, sizeof metres, "%.3g m", depth);
    warnings.push_back(scene.path + ": warning: " + name(pair.first) + " and " + name(pair.second) + " overlap by " +
                       metres + " at the start; the solver pushes them apart in the first steps");
    if (warnings.size() == 10) break;  // enough to see what is wrong
  }
  return warnings;
}

}  // namespace impulse::demos
