// The physics benchmark's scenes (../shared/bench/SCENES.md), described once without any engine
// so that impulse, Bullet and Box3D get exactly the same bodies, and the measurement loop that
// every engine's run shares.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace impulse::bench {

struct V3 {
  double x = 0, y = 0, z = 0;
};
inline double distance(const V3& a, const V3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;
};

enum class Kind { box, sphere };

struct BodySpec {
  Kind kind = Kind::box;
  V3 half{0.5, 0.5, 0.5};  // box half extents, m
  double radius = 0.5;     // sphere, m
  bool is_static = false;  // else unit mass
  V3 position;
  Quaternion orientation;
};

// Every engine gives every body this material: Bullet's defaults.
constexpr double kFriction = 0.5;
constexpr double kRestitution = 0;
constexpr double kTimeStep = 1.0 / 60;
constexpr double kMovingSpeed = 0.05;  // m/s: faster than this at the end counts as still moving

struct Scene {
  std::string name;
  std::vector<BodySpec> bodies;  // the static ones first
  int top = -1;                  // index among the dynamic bodies of the box whose drift counts, or -1
  bool any_drift = false;        // also the largest drift of any dynamic body (pyramids)
  int dynamic_count() const {
    return int(std::count_if(bodies.begin(), bodies.end(), [](const BodySpec& b) { return !b.is_static; }));
  }
};

// Names: stack-10, stack-20, pyramid, large-pyramid, boxes, spheres. Throws std::invalid_argument
// for another name.
Scene make_scene(const std::string& name);

// One run of a scene: how long, and with sleeping on or off.
struct Run {
  std::string scene;
  int steps = 0;
  bool sleep = false;
  bool extra = false;  // not asked for by SCENES.md (added for the goals)
};

// What a run gives; plain data, so that a forked child can send it back through a pipe.
struct RunResult {
  bool ok = false;
  char error[240] = {};
  int steps = 0;
  int bodies = 0;                // dynamic
  double build_s = 0;            // s to create the world and its bodies
  double median_ms = 0, p90_ms = 0, max_ms = 0, mean_ms = 0;
  double top_drift = -1;         // m, largest over the run; -1: not measured
  double any_drift = -1;         // m, largest of any dynamic body over the run; -1: not measured
  double asleep_at = -1;         // s, first time every dynamic body sleeps; -1: never
  int moving = 0;                // dynamic bodies faster than kMovingSpeed at the end
  int sunk = 0;                  // dynamic bodies whose centre ended below the ground's top (y < 0)
  double substeps = 0;           // solver sub-steps a step, mean over the run; 0: the engine has none
};

// The loop every engine shares. Engine: step(); V3 position(i) and double speed(i) for dynamic
// body i (in scene order); bool all_asleep(); and, if it has them, int substeps() of the last step.
// Only step() is timed.
template <class Engine>
void measure(Engine& engine, const Scene& scene, const Run& run, RunResult& out) {
  const int n = scene.dynamic_count();
  std::vector<V3> start(n);
  for (int i = 0; i < n; ++i) start[i] = engine.position(i);
  std::vector<double> ms;
  ms.reserve(run.steps);
  double top_drift = 0, any_drift = 0, substeps = 0;
  for (int s = 0; s < run.steps; ++s) {
    const auto t0 = std::chrono::steady_clock::now();
    engine.step();
    const auto t1 = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    if constexpr (requires { engine.substeps(); }) substeps += engine.substeps();
    if (scene.top >= 0) top_drift = std::max(top_drift, distance(engine.position(scene.top), start[scene.top]));
    if (scene.any_drift)
      for (int i = 0; i < n; ++i) any_drift = std::max(any_drift, distance(engine.position(i), start[i]));
    if (run.sleep && out.asleep_at < 0 && engine.all_asleep()) out.asleep_at = (s + 1) * kTimeStep;
  }
  out.steps = run.steps;
  out.bodies = n;
  if (run.steps > 0) out.substeps = substeps / run.steps;
  if (scene.top >= 0) out.top_drift = top_drift;
  if (scene.any_drift) out.any_drift = any_drift;
  for (int i = 0; i < n; ++i) {
    if (engine.speed(i) > kMovingSpeed) ++out.moving;
    if (engine.position(i).y < 0) ++out.sunk;
  }
  double sum = 0;
  for (double m : ms) sum += m;
  std::sort(ms.begin(), ms.end());
  if (!ms.empty()) {
    const size_t k = ms.size();
    out.median_ms = k % 2 ? ms[k / 2] : (ms[k / 2 - 1] + ms[k / 2]) / 2;
    out.p90_ms = ms[size_t(std::ceil(0.9 * double(k))) - 1];  // nearest rank
    out.max_ms = ms.back();
    out.mean_ms = sum / double(k);
  }
  out.ok = true;
}

// The engines (impulse_scenes.cpp, bullet_scenes.cpp, box3d_scenes.cpp). They throw on failure.
// Box3D's are defined only in a build with Box3D (IMPULSE_BENCH_HAVE_BOX3D).
void run_impulse(const Scene& scene, const Run& run, RunResult& out);
// impulse's WorldSettings::threads in the runs (0, the default: one per core, shared while faster).
extern int impulse_threads;
void run_bullet(const Scene& scene, const Run& run, RunResult& out);
std::string bullet_description();  // version and precision
void run_box3d(const Scene& scene, const Run& run, RunResult& out);
// Box3D's sub-steps per step (4, its default; --box3d-substeps: the same solver made stiffer).
extern int box3d_substeps;
extern int box3d_workers;  // 0: as many as impulse's team has threads (ThreadTeam::default_size())
std::string box3d_description();  // version, sub-steps, workers, precision

}  // namespace impulse::bench
