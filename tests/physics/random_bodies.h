// Random crowds of bodies for the broad phase's and the contact finder's tests.
#pragma once
#include "physics/body.h"

#include <random>
#include <vector>

namespace impulse::physics::test {

// 500 boxes and spheres of mixed sizes, turned and moving at random in a 12 m cube (crowded
// enough for thousands of overlaps), some static, some asleep; and a ground plane.
inline std::vector<Body> random_bodies(unsigned seed, std::vector<uint8_t>& awake) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> unit(-1, 1), size(0.05, 0.8);
  std::vector<Body> bodies;
  BodyDef plane;
  plane.shape = Shape::plane(Vec3(0.1, 1, 0).normalized(), -3);
  bodies.push_back(make_body(plane));
  for (int i = 0; i < 500; ++i) {
    BodyDef def;
    def.shape = i % 3 == 0 ? Shape::sphere(size(rng)) : Shape::box(Vec3(size(rng), size(rng), size(rng)));
    def.position = Vec3(unit(rng), unit(rng), unit(rng)) * 6;
    def.orientation = Quat(unit(rng), unit(rng), unit(rng), unit(rng));
    def.is_static = i % 17 == 0;
    if (!def.is_static) {
      def.velocity = Vec3(unit(rng), unit(rng), unit(rng)) * 10;
      def.angular_velocity = Vec3(unit(rng), unit(rng), unit(rng)) * 5;
    }
    bodies.push_back(make_body(def));
  }
  awake.assign(bodies.size(), 0);
  for (size_t i = 0; i < bodies.size(); ++i) awake[i] = !bodies[i].is_static() && i % 11 != 0;
  return bodies;
}

}  // namespace impulse::physics::test
