// The benchmark's scenes in impulse: physics::World with its default settings, sleeping as the
// run asks.
#include "tests/bench/physics_scenes.h"

#include "physics/world.h"

namespace impulse::bench {

int impulse_threads = 0;

namespace {

class ImpulseEngine {
 public:
  ImpulseEngine(const Scene& scene, bool sleep) : world_(settings(sleep)) {
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
      const BodySpec& spec = scene.bodies[i];
      physics::BodyDef def;
      def.name = (spec.kind == Kind::box ? "box " : "sphere ") + std::to_string(i);
      def.shape = spec.kind == Kind::box ? physics::Shape::box({spec.half.x, spec.half.y, spec.half.z})
                                         : physics::Shape::sphere(spec.radius);
      def.is_static = spec.is_static;
      def.mass = 1;
      def.material = {kRestitution, kFriction};
      def.position = {spec.position.x, spec.position.y, spec.position.z};
      def.orientation = physics::Quat(spec.orientation.w, spec.orientation.x, spec.orientation.y, spec.orientation.z);
      const int index = world_.add_body(def);
      if (!spec.is_static) dynamic_.push_back(index);
    }
  }

  void step() { world_.step(); }
  int substeps() const { return world_.substeps(); }
  V3 position(int i) const {
    const physics::Vec3& p = world_.bodies()[dynamic_[i]].position;
    return {p.x(), p.y(), p.z()};
  }
  double speed(int i) const { return world_.bodies()[dynamic_[i]].velocity.norm(); }
  bool all_asleep() const {
    for (int i : dynamic_)
      if (world_.bodies()[i].awake) return false;
    return true;
  }

 private:
  static physics::WorldSettings settings(bool sleep) {
    physics::WorldSettings s;
    s.gravity = {0, -9.81, 0};
    s.time_step = kTimeStep;
    s.sleep.enabled = sleep;
    s.threads = impulse_threads;
    return s;
  }

  physics::World world_;
  std::vector<int> dynamic_;
};

}  // namespace

void run_impulse(const Scene& scene, const Run& run, RunResult& out) {
  const auto t0 = std::chrono::steady_clock::now();
  ImpulseEngine engine(scene, run.sleep);
  out.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  measure(engine, scene, run, out);
}

std::string impulse_description() {
  const physics::WorldSettings s;
  return "impulse (" + std::to_string(s.min_substeps) + " to " + std::to_string(s.substeps) + " sub-steps for stacks sinking < " +
         std::to_string(int(s.stack_sink * 1000)) + " mm, contact hertz " + std::to_string(int(s.contact.contact_hertz)) + ", " +
         (impulse_threads > 0 ? std::to_string(impulse_threads) + " threads always"
                              : std::to_string(physics::ThreadTeam::default_size()) + " threads (default: shared while faster)") + ", " + (sizeof(physics::Real) == 8 ? "double" : "single") +
         " precision)";
}

}  // namespace impulse::bench
