// Where the boxes of a pyramid go: rows of boxes of edge `size`, each row one box shorter and half
// a box further in than the row below, centred on x = 0 of `origin` (the middle of the base row's
// bottom), in the x-y plane. The benchmark's, the tests' and the scene files' pyramids all use it.
#pragma once
#include <vector>

#include "physics/math.h"

namespace impulse::physics {

struct PyramidBox {
  int row = 0;     // 0 at the bottom
  int column = 0;  // 0 at the left (-x) of its row
  Vec3 centre = Vec3::Zero();
};

// Bottom row first, each row from -x to +x: base * (base + 1) / 2 boxes.
std::vector<PyramidBox> pyramid_boxes(int base, Real size = 1, const Vec3& origin = Vec3::Zero());

}  // namespace impulse::physics
