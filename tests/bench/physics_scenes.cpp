#include "tests/bench/physics_scenes.h"

#include "physics/pyramid.h"

#include <numbers>
#include <stdexcept>

namespace impulse::bench {

namespace {

// Seeded and the same on every standard library (std's distributions are not): splitmix64.
class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  double uniform() {  // [0, 1)
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
  }
  double centred(double width) { return (uniform() - 0.5) * width; }  // uniform over [-width/2, width/2)
  Quaternion orientation() {  // uniform over rotations (Shoemake)
    const double u1 = uniform(), u2 = 2 * std::numbers::pi * uniform(), u3 = 2 * std::numbers::pi * uniform();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    return {b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3)};
  }

 private:
  uint64_t state_;
};

BodySpec static_box(const V3& half, const V3& position) {
  BodySpec b;
  b.kind = Kind::box;
  b.half = half;
  b.is_static = true;
  b.position = position;
  return b;
}

BodySpec ground() { return static_box({100, 0.5, 100}, {0, -0.5, 0}); }

BodySpec unit_cube(const V3& position, const Quaternion& orientation = {}) {
  BodySpec b;
  b.kind = Kind::box;
  b.half = {0.5, 0.5, 0.5};
  b.position = position;
  b.orientation = orientation;
  return b;
}

Scene stack(int n) {
  Scene s;
  s.name = "stack-" + std::to_string(n);
  s.bodies.push_back(ground());
  for (int i = 0; i < n; ++i) s.bodies.push_back(unit_cube({0, 0.5 + i, 0}));
  s.top = n - 1;
  return s;
}

Scene pyramid(const std::string& name, int base) {
  Scene s;
  s.name = name;
  s.bodies.push_back(ground());
  for (const physics::PyramidBox& box : physics::pyramid_boxes(base)) s.bodies.push_back(unit_cube({box.centre.x(), box.centre.y(), box.centre.z()}));
  s.top = s.dynamic_count() - 1;
  s.any_drift = true;
  return s;
}

Scene boxes(uint64_t seed) {
  Scene s;
  s.name = "boxes";
  s.bodies.push_back(ground());
  Random random(seed);
  for (int layer = 0; layer < 10; ++layer) {
    const double shift = layer % 2 ? 1 : 0;
    for (int i = 0; i < 10; ++i)
      for (int k = 0; k < 10; ++k) {
        const double x = (i - 4.5) * 2 + shift + random.centred(0.1);
        const double z = (k - 4.5) * 2 + shift + random.centred(0.1);
        s.bodies.push_back(unit_cube({x, 1.5 + 2 * layer, z}, random.orientation()));
      }
  }
  return s;
}

Scene spheres() {
  Scene s;
  s.name = "spheres";
  s.bodies.push_back(ground());
  s.bodies.push_back(static_box({0.25, 3, 4.5}, {-4.25, 3, 0}));
  s.bodies.push_back(static_box({0.25, 3, 4.5}, {4.25, 3, 0}));
  s.bodies.push_back(static_box({4.5, 3, 0.25}, {0, 3, -4.25}));
  s.bodies.push_back(static_box({4.5, 3, 0.25}, {0, 3, 4.25}));
  Random random(5);
  for (int layer = 0; layer < 10; ++layer)
    for (int i = 0; i < 10; ++i)
      for (int k = 0; k < 10; ++k) {
        BodySpec b;
        b.kind = Kind::sphere;
        b.radius = 0.25;
        b.position = {(i - 4.5) * 0.75 + random.centred(0.1), 3 + 3 * layer + random.centred(0.5),
                      (k - 4.5) * 0.75 + random.centred(0.1)};
        s.bodies.push_back(b);
      }
  return s;
}

}  // namespace

Scene make_scene(const std::string& name) {
  if (name == "stack-10") return stack(10);
  if (name == "stack-20") return stack(20);
  if (name == "pyramid") return pyramid(name, 20);
  if (name == "large-pyramid") return pyramid(name, 100);
  if (name == "boxes") return boxes(4);
  if (name.starts_with("boxes:")) return boxes(std::stoull(name.substr(6)));  // another seed, for tools
  if (name == "spheres") return spheres();
  throw std::invalid_argument("unknown scene '" + name + "'");
}

}  // namespace impulse::bench
