#include "demos/scene/scene_world.h"

namespace impulse::demos {

physics::World build_world(const Scene& scene) {
  physics::World world(scene.world);
  for (const physics::BodyDef& def : scene.bodies) world.add_body(def);
  for (const physics::JointDef& def : scene.joints) world.add_joint(def);  // by index into bodies
  return world;
}

}  // namespace impulse::demos
