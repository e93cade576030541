// A scene of ../shared/bench/SCENES.md (tests/bench/physics_scenes.h) as an impulse World, for
// the tests that run the benchmark's heaps: every body 1 kg with `material`.
#pragma once
#include <string>

#include "physics/world.h"
#include "tests/bench/physics_scenes.h"

namespace impulse::physics::test {

inline World bench_world(const std::string& name, const WorldSettings& settings, Material material) {
  const bench::Scene scene = bench::make_scene(name);
  World world(settings);
  for (const bench::BodySpec& spec : scene.bodies) {
    BodyDef def;
    def.shape = spec.kind == bench::Kind::box ? Shape::box({spec.half.x, spec.half.y, spec.half.z}) : Shape::sphere(spec.radius);
    def.is_static = spec.is_static;
    def.mass = 1;
    def.material = material;
    def.position = {spec.position.x, spec.position.y, spec.position.z};
    def.orientation = Quat(spec.orientation.w, spec.orientation.x, spec.orientation.y, spec.orientation.z);
    world.add_body(def);
  }
  return world;
}

}  // namespace impulse::physics::test
