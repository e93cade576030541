#include "physics/island.h"

#include <algorithm>
#include <numeric>

namespace impulse::physics {

namespace {
bool is_dynamic(const Body& body) { return body.inv_mass > 0; }
}  // namespace

int Islands::find(int i) {
  while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
  return i;
}

void Islands::join(int a, int b) {
  a = find(a);
  b = find(b);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);
}

void Islands::update(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                     const std::vector<std::pair<int, int>>& links, const std::vector<int>& anchored, bool friction,
                     Real touching_distance, Real dt, const SleepSettings& settings) {
  const int n = int(bodies.size());
  island_of_.resize(n, -1);
  if (!settings.enabled) return;

  // Sleep timers: the fastest point of the body must stay below the tolerance.
  for (Body& body : bodies) {
    if (!is_dynamic(body) || !body.awake) continue;
    const Real speed = body.velocity.norm() + body.angular_velocity.norm() * bounding_radius(body.shape);
    body.sleep_time = speed > settings.velocity_tolerance ? 0 : body.sleep_time + dt;
  }

  // Islands of awake bodies, joined through touching contacts and links (static bodies join nothing).
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0);
  for (const Contact& c : contacts)
    if (c.separation < touching_distance && is_dynamic(bodies[c.body_a]) && is_dynamic(bodies[c.body_b]))
      join(c.body_a, c.body_b);
  for (const auto& [a, b] : links)
    if (is_dynamic(bodies[a]) && is_dynamic(bodies[b])) join(a, b);

  // What holds each island: friction against a still body (static, or asleep), or a joint to the world.
  std::vector<char> held(n, 0), moving(n, 0);
  const auto still = [&](const Body& body) { return !is_dynamic(body) || !body.awake; };
  if (friction) {
    for (const Contact& c : contacts) {
      const Body& a = bodies[c.body_a];
      const Body& b = bodies[c.body_b];
      if (c.separation >= touching_distance || !(a.material.friction > 0 && b.material.friction > 0)) continue;
      if (still(b) && !still(a)) held[find(c.body_a)] = 1;
      if (still(a) && !still(b)) held[find(c.body_b)] = 1;
    }
  }
  for (const int i : anchored) held[find(i)] = 1;
  for (const auto& [a, b] : links) {
    if (!is_dynamic(bodies[a]) && is_dynamic(bodies[b])) held[find(b)] = 1;
    if (!is_dynamic(bodies[b]) && is_dynamic(bodies[a])) held[find(a)] = 1;
  }
  // An island sleeps when its most restless body has rested long enough, and something holds it
  // or it is exactly still.
  std::vector<Real> least_rest(n, INFINITY);
  for (int i = 0; i < n; ++i) {
    if (!is_dynamic(bodies[i]) || !bodies[i].awake) continue;
    least_rest[find(i)] = std::min(least_rest[find(i)], bodies[i].sleep_time);
    if (bodies[i].velocity != Vec3::Zero() || bodies[i].angular_velocity != Vec3::Zero()) moving[find(i)] = 1;
  }
  for (int i = 0; i < n; ++i) {
    Body& body = bodies[i];
    if (!is_dynamic(body) || !body.awake || least_rest[find(i)] < settings.time_to_sleep) continue;
    if (!held[find(i)] && moving[find(i)]) continue;
    body.awake = false;
    body.velocity.setZero();
    body.angular_velocity.setZero();
    island_of_[i] = find(i);
  }
}

void Islands::wake_island(std::vector<Body>& bodies, int island) {
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (island_of_[i] != island) continue;
    bodies[i].awake = true;
    bodies[i].sleep_time = 0;
    island_of_[i] = -1;
  }
}

bool Islands::wake_touched(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                           const std::vector<std::pair<int, int>>& links, Real touching_distance,
                           const SleepSettings& settings) {
  island_of_.resize(bodies.size(), -1);
  bool woke = false;
  // A contact wakes a sleeper when it touches, or when the awake body closes on it: a ball
  // thrown at a sleeping stack wakes it before it arrives (the solver would take the sleeper
  // for static), while a neighbour merely resting nearby leaves it asleep. Were any nearby
  // contact to wake it, a resting heap could never sleep: each island that fell asleep was
  // woken at once by the next one, a few millimetres away.
  auto wakes = [&](const Contact& c) {
    if (c.separation < touching_distance) return true;
    const Body& a = bodies[c.body_a];
    const Body& b = bodies[c.body_b];
    const Vec3 va = a.velocity + a.angular_velocity.cross(c.point - a.position);
    const Vec3 vb = b.velocity + b.angular_velocity.cross(c.point - b.position);
    return -(va - vb).dot(c.normal) > settings.velocity_tolerance;  // closing
  };
  auto consider = [&](int a, int b) {
    const Body& ba = bodies[a];
    const Body& bb = bodies[b];
    if (!is_dynamic(ba) || !is_dynamic(bb) || ba.awake == bb.awake) return;
    const int sleeper = ba.awake ? b : a;
    if (island_of_[sleeper] >= 0) wake_island(bodies, island_of_[sleeper]);
    bodies[sleeper].awake = true;  // also one put to sleep by hand, outside any island
    bodies[sleeper].sleep_time = 0;
    woke = true;
  };
  for (const Contact& c : contacts)
    if (wakes(c)) consider(c.body_a, c.body_b);
  for (const auto& [a, b] : links) consider(a, b);
  return woke;
}

}  // namespace impulse::physics
