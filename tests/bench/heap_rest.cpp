// heap_rest: exercise 4 on the heaps of ../shared/bench/SCENES.md with sleeping off: do they come to rest?
// For each heap, friction and restitution asked for, it runs 60 s on one thread and prints the
// fastest body (|v| + |w| r, r its bounding radius: its fastest point) at 20, 40 and 60 s, the
// fastest from 20 s to 60 s, and how many bodies are above 1 mm/s at 60 s.
//
//   heap_rest [boxes|spheres|both] [mu,...] [e,...] [seconds]
//   heap_rest both 0.4,0.5,0.6 0,0.5 60      (the default: the twelve configurations)
//   heap_rest rocking                        (a box recorded rocking in the heap, see rocking_box)
// The environment sets the world: ROLL=c contact.rolling_resistance, DAMP=z its damping ratio,
// HERTZ=f its stiffness, SUBSTEPS=n that many sub-steps always. TRACE=1 prints the fastest body's
// contact points each step over the last 2 s (FOLLOW=i: body i's instead); MONITOR=1 prints the
// fastest body, the count above 1 mm/s and the sub-steps each second from 20 s. SEED=n drops the
// boxes from another seed (SCENES.md's is 4): one heap is one sample of a chaotic pile.
#include "tests/bench/bench_world.h"
#include "tests/physics/physics_test_scenes.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace impulse::physics;
using test::point_speed;

std::vector<Real> numbers(const std::string& text) {
  std::vector<Real> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::strtod(item.c_str(), nullptr));
  return out;
}

// The fastest body from the first traced step on (or FOLLOW's): its speed, height and kinetic
// energy, and each of its contact points: the other body, penetration, normal impulse and how
// much of mu N friction uses.
void trace(World& world, int step, Real mu) {
  static int body = std::getenv("FOLLOW") ? std::atoi(std::getenv("FOLLOW")) : -1;
  if (body < 0) {
    Real fastest = 0;
    for (int i = 0; i < int(world.bodies().size()); ++i)
      if (!world.bodies()[i].is_static() && point_speed(world.bodies()[i]) > fastest) fastest = point_speed(world.bodies()[body = i]);
  }
  const Body& b = world.bodies()[body];
  const Real energy = b.velocity.squaredNorm() / (2 * b.inv_mass) + b.angular_velocity.dot(b.inv_inertia_world.inverse() * b.angular_velocity) / 2;
  std::printf("%d body %d v %.4f w %.4f y %.5f KE %.2e |", step, body, b.velocity.norm(), b.angular_velocity.norm(), b.position.y(), energy);
  for (const ContactRecord& c : world.record().contacts) {
    if (c.body_a != body && c.body_b != body) continue;
    std::printf(" %d:%.2fmm/%.3f/%.2f", c.body_a == body ? c.body_b : c.body_a, 1e3 * c.penetration, c.normal_impulse,
                c.normal_impulse > 0 ? c.tangent_impulse.norm() / (mu * c.normal_impulse) : 0.0);
  }
  std::printf("\n");
}

// Sleeping off, one thread, and what the environment sets.
WorldSettings settings_from_environment() {
  WorldSettings settings;
  settings.sleep.enabled = false;
  settings.threads = 1;
  if (const char* roll = std::getenv("ROLL")) settings.contact.rolling_resistance = std::strtod(roll, nullptr);
  if (const char* damp = std::getenv("DAMP")) settings.contact.contact_damping_ratio = std::strtod(damp, nullptr);
  if (const char* sub = std::getenv("SUBSTEPS")) {
    settings.substeps = std::atoi(sub);
    settings.stack_sink = 0;
  }
  if (const char* hertz = std::getenv("HERTZ")) settings.contact.contact_hertz = std::strtod(hertz, nullptr);
  return settings;
}

// The two boxes of test::add_rocking_boxes, on their still supports. Prints both moving boxes'
// fastest point each second for 10 s.
void rocking_box() {
  World world(settings_from_environment());
  const std::vector<int> moving = test::add_rocking_boxes(world);
  std::printf("rocking box: fastest point of the upper and the lower box, mm/s\n");
  for (int step = 1; step <= 10 * 60; ++step) {
    world.step();
    if (std::getenv("TRACE")) trace(world, step, 0.5);
    if (step % 60 == 0)
      std::printf("%3d s  %10.3f %10.3f\n", step / 60, 1e3 * point_speed(world.bodies()[moving[0]]), 1e3 * point_speed(world.bodies()[moving[1]]));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "both";
  if (which == "rocking") {
    rocking_box();
    return 0;
  }
  const std::vector<Real> mus = numbers(argc > 2 ? argv[2] : "0.4,0.5,0.6");
  const std::vector<Real> es = numbers(argc > 3 ? argv[3] : "0,0.5");
  const int seconds = argc > 4 ? std::atoi(argv[4]) : 60;
  std::vector<std::string> heaps;
  if (which == "both" || which == "boxes") heaps.push_back("boxes");
  if (which == "both" || which == "spheres") heaps.push_back("spheres");
  std::printf("%-8s %4s %4s %10s %10s %10s %12s %8s\n", "heap", "mu", "e", "20s mm/s", "40s mm/s", "60s mm/s", "max>=20s", ">1mm/s");
  for (const std::string& heap : heaps)
    for (Real mu : mus)
      for (Real e : es) {
        const char* seed = std::getenv("SEED");
        World world = test::bench_world(heap == "boxes" && seed ? "boxes:" + std::string(seed) : heap, settings_from_environment(), {e, mu});
        Real at[3] = {0, 0, 0}, late = 0;
        int above = 0;
        for (int step = 1; step <= seconds * 60; ++step) {
          world.step();
          if (step < 20 * 60) continue;
          Real fastest = 0;
          int count = 0, fastest_body = -1;
          for (const Body& body : world.bodies()) {
            if (body.is_static()) continue;
            const Real speed = point_speed(body);
            if (speed > fastest) {
              fastest = speed;
              fastest_body = int(&body - world.bodies().data());
            }
            count += speed > 1e-3;
          }
          if (std::getenv("MONITOR") && step % 60 == 0)
            std::printf("  %3d s: fastest %7.3f mm/s (body %d at y %.2f), %d above 1 mm/s, %d sub-steps\n", step / 60, 1e3 * fastest, fastest_body,
                        fastest_body < 0 ? 0.0 : world.bodies()[fastest_body].position.y(), count, world.substeps());
          late = std::max(late, fastest);
          if (step % (20 * 60) == 0 && step / (20 * 60) <= 3) at[step / (20 * 60) - 1] = fastest;
          above = count;
          if (std::getenv("TRACE") && step >= (seconds - 2) * 60) trace(world, step, mu);
        }
        std::printf("%-8s %4.1f %4.1f %10.3f %10.3f %10.3f %12.3f %8d\n", heap.c_str(), mu, e, 1e3 * at[0], 1e3 * at[1], 1e3 * at[2],
                    1e3 * late, above);
        std::fflush(stdout);
      }
}
