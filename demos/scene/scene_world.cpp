#include "demos/scene/scene_world.h"

#include "physics/broadphase.h"
#include "physics/collide.h"

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
  // The bodies where they start, paired as a world's first step pairs them (physics/collide.h),
  // without a world: only the overlaps count, nothing moves.
  std::vector<physics::Body> bodies;
  std::vector<physics::Aabb> boxes;
  for (const physics::BodyDef& def : scene.bodies) {
    bodies.push_back(physics::make_body(def));
    boxes.push_back(physics::body_aabb(bodies.back(), 0));
  }
  std::map<std::pair<int, int>, double> deepest;  // per pair of bodies
  std::vector<physics::Contact> contacts;
  for (size_t i = 0; i < bodies.size(); ++i)
    for (size_t j = i + 1; j < bodies.size(); ++j) {
      if ((bodies[i].is_static() && bodies[j].is_static()) || !physics::overlap(boxes[i], boxes[j])) continue;
      contacts.clear();
      physics::collide(bodies[i], int(i), bodies[j], int(j), 0, contacts);
      for (const physics::Contact& contact : contacts)
        if (contact.penetration() > kOverlap) {
          double& depth = deepest[{contact.body_a, contact.body_b}];
          depth = std::max(depth, double(contact.penetration()));
        }
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
