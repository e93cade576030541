#include "render/level_of_detail.h"

#include <cmath>

namespace impulse::render {

int sphere_level(float radius, float tolerance) {
  float error = 0.204f * radius;  // level 0
  int level = 1;                   // the icosahedron itself is never round enough to show
  error /= 4.0f;
  while (level < kMaxSphereLevel && !(error <= tolerance)) {
    error /= 4.0f;
    ++level;
  }
  return level;
}

}  // namespace impulse::render
