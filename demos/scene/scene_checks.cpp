#include "demos/scene/scene_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::demos {
namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

physics::Vec3 momentum(const physics::World& world) {
  physics::Vec3 p = physics::Vec3::Zero();
  for (const physics::Body& body : world.bodies())
    if (!body.is_static()) p += body.mass * body.velocity;
  return p;
}

double energy(const physics::World& world) {
  const physics::StepRecord& record = world.record();
  return record.kinetic_energy + record.potential_energy;
}

// The body's lowest point above y = 0: its centre less its reach downwards.
double bottom(const physics::Body& body) {
  if (body.shape.type == physics::ShapeType::plane) return body.position.y();
  return body.position.y() - physics::reach_along(body.shape, body.orientation, -physics::Vec3::UnitY());
}

}  // namespace

CheckWatch::CheckWatch(std::vector<CheckSpec> checks) : checks_(std::move(checks)), states_(checks_.size()) {}

void CheckWatch::start(const physics::World& world) {
  for (size_t i = 0; i < checks_.size(); ++i)
    if (checks_[i].kind == "height" && checks_[i].body >= 0) states_[i].start_value = bottom(world.bodies()[checks_[i].body]);
  observe(world, world.time(), true);
}

void CheckWatch::step(const physics::World& world) { observe(world, world.time(), false); }

void CheckWatch::observe(const physics::World& world, double time, bool first) {
  for (size_t i = 0; i < checks_.size(); ++i) {
    const CheckSpec& check = checks_[i];
    State& state = states_[i];
    if (time < check.from - 1e-9 || time > check.to + 1e-9) continue;
    const physics::Body* body = check.body >= 0 ? &world.bodies()[check.body] : nullptr;
    const bool begins = !state.seen;
    state.seen = true;
    if (check.kind == "momentum") {
      if (begins) state.start_vector = momentum(world);
      state.extreme = std::max(state.extreme, (momentum(world) - state.start_vector).norm());
    } else if (check.kind == "energy") {
      if (begins) state.start_value = energy(world);
      state.extreme = std::max(state.extreme, energy(world) - state.start_value);
    } else if (check.kind == "at_rest") {
      state.extreme = std::max(state.extreme, body->velocity.norm());
    } else if (check.kind == "inside" || check.kind == "drift") {
      if (begins) state.start_vector = body->position;
      state.last = body->position;
    } else if (check.kind == "velocity") {
      state.last = body->velocity;
    } else if (check.kind == "height") {
      state.extreme = begins ? bottom(*body) : std::max(state.extreme, bottom(*body));
    } else if (check.kind == "penetration" && !first) {
      for (const physics::ContactRecord& contact : world.record().contacts)
        state.extreme = std::max(state.extreme, double(contact.penetration));
    }
  }
}

std::vector<CheckResult> CheckWatch::results() const {
  std::vector<CheckResult> results;
  for (size_t i = 0; i < checks_.size(); ++i) {
    const CheckSpec& check = checks_[i];
    const State& state = states_[i];
    CheckResult result{check.text, false, ""};
    if (!state.seen) {
      result.measured = "its window was never simulated (from " + format("%g", check.from) + " s)";
    } else if (check.kind == "momentum") {
      result.passed = state.extreme <= check.tolerance;
      result.measured = format("changed by %.3g kg m/s (at most %.3g)", state.extreme, check.tolerance);
    } else if (check.kind == "energy") {
      const double share = state.extreme / std::max(std::abs(state.start_value), 1e-12);
      result.passed = share <= check.tolerance;
      result.measured = format("rose by at most %.3g J, %.3g %% of its start (allowed: %.3g %%)", std::max(state.extreme, 0.0),
                               100 * std::max(share, 0.0), 100 * check.tolerance);
    } else if (check.kind == "at_rest") {
      result.passed = state.extreme < check.speed;
      result.measured = format("fastest %.3g m/s (below %.3g)", state.extreme, check.speed);
    } else if (check.kind == "inside") {
      result.passed = (state.last.array() >= check.min.array()).all() && (state.last.array() <= check.max.array()).all();
      result.measured = format("ended at [%.3g, %.3g, %.3g] m", state.last.x(), state.last.y(), state.last.z());
    } else if (check.kind == "velocity") {
      result.passed = (state.last.array() >= check.min.array()).all() && (state.last.array() <= check.max.array()).all();
      result.measured = format("ended at [%.3g, %.3g, %.3g] m/s", state.last.x(), state.last.y(), state.last.z());
    } else if (check.kind == "drift") {
      const double moved = (state.last - state.start_vector).norm();
      result.passed = moved <= check.distance;
      result.measured = format("moved %.3g m (at most %.3g)", moved, check.distance);
    } else if (check.kind == "height") {
      if (check.ratio > 0) {
        const double ratio = state.extreme / std::max(state.start_value, 1e-12);
        result.passed = std::abs(ratio - check.ratio) <= check.tolerance;
        result.measured = format("rose to %.3f of its starting height (%.3g ± %.3g)", ratio, check.ratio, check.tolerance);
      } else {
        result.passed = state.extreme >= check.min.y() && state.extreme <= check.max.y();
        result.measured = format("rose to %.3g m (%.3g .. %.3g)", state.extreme, check.min.y(), check.max.y());
      }
    } else if (check.kind == "penetration") {
      result.passed = state.extreme <= check.depth;
      result.measured = format("deepest %.3g m (at most %.3g)", state.extreme, check.depth);
    }
    results.push_back(result);
  }
  return results;
}

}  // namespace impulse::demos
