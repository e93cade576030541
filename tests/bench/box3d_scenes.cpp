// The benchmark's scenes in Box3D (the second peer, ../shared/peers/box3d, see its PEER.md):
// b3DefaultWorldDef() with our gravity and sleeping as the run asks, b3World_Step(world, 1/60, 4)
// (4 sub-steps is Box3D's default; --box3d-substeps N sets another), and as many workers as impulse has threads
// (ThreadTeam::default_size(); one in --duel), run by Box3D's own scheduler: with workerCount > 1 and no task
// callbacks, b3CreateWorld starts workerCount - 1 threads and the stepping thread is worker 0,
// as impulse's team counts the caller. Only this file includes Box3D; it is compiled only when
// CMake found the peer (IMPULSE_BENCH_BOX3D).
#include "tests/bench/physics_scenes.h"

#include "physics/thread_team.h"

#include <box3d/box3d.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace impulse::bench {

int box3d_substeps = 4;
int box3d_workers = 0;

namespace {

int workers() { return box3d_workers > 0 ? box3d_workers : physics::ThreadTeam::default_size(); }

class Box3DEngine {
 public:
  Box3DEngine(const Scene& scene, bool sleep) {
    b3WorldDef def = b3DefaultWorldDef();
    def.gravity = {0, -9.81f, 0};
    def.enableSleep = sleep;
    def.workerCount = uint32_t(workers());
    world_ = b3CreateWorld(&def);
    for (const BodySpec& spec : scene.bodies) {
      b3BodyDef body_def = b3DefaultBodyDef();
      body_def.type = spec.is_static ? b3_staticBody : b3_dynamicBody;
      body_def.position = {float(spec.position.x), float(spec.position.y), float(spec.position.z)};
      body_def.rotation = {{float(spec.orientation.x), float(spec.orientation.y), float(spec.orientation.z)},
                           float(spec.orientation.w)};
      const b3BodyId body = b3CreateBody(world_, &body_def);

      // The material: Box3D mixes friction as sqrt(a * b) (as impulse does) and restitution as
      // max(a, b), so every contact gets exactly kFriction and kRestitution. Rolling resistance
      // stays at its default 0, as in the other engines.
      b3ShapeDef shape_def = b3DefaultShapeDef();
      shape_def.baseMaterial.friction = float(kFriction);
      shape_def.baseMaterial.restitution = float(kRestitution);
      // Box3D takes a density; a unit mass is 1 / volume (a static body's density is ignored).
      if (spec.kind == Kind::sphere) {
        shape_def.density = float(1 / (4.0 / 3 * std::numbers::pi * spec.radius * spec.radius * spec.radius));
        const b3Sphere sphere{{0, 0, 0}, float(spec.radius)};
        b3CreateSphereShape(body, &shape_def, &sphere);
      } else {
        shape_def.density = float(1 / (8 * spec.half.x * spec.half.y * spec.half.z));
        const b3BoxHull box = b3MakeBoxHull(float(spec.half.x), float(spec.half.y), float(spec.half.z));
        b3CreateHullShape(body, &shape_def, &box.base);
      }
      if (!spec.is_static) {
        // The scenes promise unit mass; a density that missed it would make another scene.
        if (std::abs(b3Body_GetMass(body) - 1) > 1e-4f) throw std::runtime_error("Box3D body mass is not 1");
        dynamic_.push_back(body);
      }
    }
  }
  ~Box3DEngine() { b3DestroyWorld(world_); }
  Box3DEngine(const Box3DEngine&) = delete;
  Box3DEngine& operator=(const Box3DEngine&) = delete;

  void step() { b3World_Step(world_, float(kTimeStep), box3d_substeps); }
  int substeps() const { return box3d_substeps; }
  V3 position(int i) const {
    const b3Pos p = b3Body_GetPosition(dynamic_[size_t(i)]);
    return {p.x, p.y, p.z};
  }
  double speed(int i) const {
    const b3Vec3 v = b3Body_GetLinearVelocity(dynamic_[size_t(i)]);
    return std::hypot(double(v.x), double(v.y), double(v.z));
  }
  // Box3D's awake set holds only non-static bodies that are awake.
  bool all_asleep() const { return b3World_GetAwakeBodyCount(world_) == 0; }

 private:
  b3WorldId world_{};
  std::vector<b3BodyId> dynamic_;
};

}  // namespace

void run_box3d(const Scene& scene, const Run& run, RunResult& out) {
  const auto t0 = std::chrono::steady_clock::now();
  Box3DEngine engine(scene, run.sleep);
  out.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  measure(engine, scene, run, out);
}

std::string box3d_description() {
  const b3Version v = b3GetVersion();
  return "Box3D " + std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.revision) + " (" +
         std::to_string(box3d_substeps) + " sub-steps, " + std::to_string(workers()) +
         (workers() == 1 ? " worker, " : " workers on its own scheduler, ") +
#ifdef BOX3D_DOUBLE_PRECISION
         "double"
#else
         "single"
#endif
         " precision)";
}

}  // namespace impulse::bench
