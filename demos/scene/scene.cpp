#include "demos/scene/scene.h"

namespace impulse::demos {

int find_body(const Scene& scene, std::string_view name) {
  for (size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].name == name) return int(i);
  return -1;
}

}  // namespace impulse::demos
