#include "physics/pyramid.h"

namespace impulse::physics {

std::vector<PyramidBox> pyramid_boxes(int base, Real size, const Vec3& origin) {
  std::vector<PyramidBox> boxes;
  for (int row = 0; row < base; ++row)
    for (int column = 0; column < base - row; ++column)
      boxes.push_back({row, column, origin + Vec3(size * (-0.5 * (base - row - 1) + column), size * (0.5 + row), 0)});
  return boxes;
}

}  // namespace impulse::physics
