// `impulse simulate`: a scene's numbers, without pictures. Steps the world once and writes CSV
// tables, one row per body per step, per contact, or per step for the world, each column headed
// with its unit. Nothing is drawn or encoded, so it costs what the physics costs.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "demos/scene/scene.h"

namespace impulse::demos {

struct TraceOptions {
  double duration = -1;      // s; < 0: the scene's
  int every = 1;             // write every Nth step (and the last)
  std::string bodies_path;   // time,step,body,position,orientation,velocity,angular velocity
  std::string contacts_path; // step,time,body_a,body_b,point,normal,penetration,normal and friction impulse
  std::string world_path;    // step,time,kinetic and potential energy,linear and angular momentum
};

// Whoever keeps a run's rows: the CSV files below, or Python's arrays (demos/python/).
class TraceSink {
 public:
  virtual ~TraceSink() = default;
  // The world after `step` steps: step 0 is the start (no contacts looked for yet), then every
  // `every`th step and the last.
  virtual void rows(long step, const physics::World& world) = 0;
};

// Steps the scene's world to `duration` (s; < 0: the scene's), handing the kept steps to `sink`,
// and `progress(steps done, steps in all)` after each step (it may throw to stop the run). The
// [[check]]s' results go to `checks` when given. Returns the steps taken.
long trace_scene(const Scene& scene, double duration, int every, TraceSink& sink, std::vector<CheckResult>* checks,
                 const std::function<void(long done, long total)>& progress = {});

// `impulse simulate`: trace_scene into the CSV files `options` names. Returns the steps taken. Throws render::OutputError when a file cannot be written; a file
// appears under its name only when complete.
// The [[check]]s' results go to `checks` when given.
long simulate_scene(const Scene& scene, const TraceOptions& options, std::vector<CheckResult>* checks = nullptr);

}  // namespace impulse::demos
