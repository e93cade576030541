#include "tests/bench/bench_frame.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace impulse::bench {
namespace {

using render::Colour;
using render::Vec3f;

// A fixed integer hash mapped to [0, 1): the same numbers on every machine and compiler.
float unit_hash(uint32_t i) {
  i ^= i >> 16;
  i *= 0x7feb352dU;
  i ^= i >> 15;
  i *= 0x846ca68bU;
  i ^= i >> 16;
  return float(i >> 8) / float(1 << 24);
}

const Colour kPalette[] = {{0.90f, 0.62f, 0.00f}, {0.34f, 0.71f, 0.91f}, {0.00f, 0.62f, 0.45f},
                           {0.80f, 0.47f, 0.65f}, {0.00f, 0.45f, 0.70f}, {0.94f, 0.89f, 0.26f}};
const Colour kNormal{0.84f, 0.37f, 0.00f};
const Colour kVelocity{0.2f, 0.2f, 0.2f};

}  // namespace

render::DrawList bench_draw_list(double t) {
  render::DrawList list;
  list.camera.position = {0.0f, 8.5f, 15.0f};
  list.camera.target = {0.0f, 0.0f, 0.5f};
  list.camera.fov_y_degrees = 50.0f;
  const float time = float(t);
  // 300 spheres: a 20 x 15 field at the back, each bobbing at its own phase and spinning; a
  // contact-normal arrow under and a velocity arrow beside 200 of them.
  for (int i = 0; i < 300; ++i) {
    const int column = i % 20, row = i / 20;
    const float radius = 0.22f + 0.12f * unit_hash(uint32_t(i));
    const float bob = 0.8f * std::abs(std::sin(2.0f * time + 6.28f * unit_hash(uint32_t(i + 1000))));
    const Vec3f centre(-9.5f + float(column), radius + bob, -9.0f + 0.9f * float(row));
    const render::Quatf spin(Eigen::AngleAxisf(time + float(i), Vec3f(0.3f, 1.0f, 0.2f).normalized()));
    list.spheres.push_back({centre, radius, spin, kPalette[i % 6]});
    if (i < 200) {
      list.arrows.push_back({centre - Vec3f(0, radius + bob, 0), Vec3f(0, 0.6f + 0.4f * bob, 0), kNormal});
      const float angle = time + 6.28f * unit_hash(uint32_t(i + 2000));
      list.arrows.push_back({centre, 0.7f * Vec3f(std::cos(angle), 0.2f, std::sin(angle)), kVelocity});
    }
  }
  // 100 boxes: a 10 x 10 block in front, each turning slowly about the vertical.
  for (int i = 0; i < 100; ++i) {
    const int column = i % 10, row = i / 10;
    const Vec3f half(0.2f + 0.08f * unit_hash(uint32_t(i + 3000)), 0.25f, 0.2f);
    const render::Quatf turn(Eigen::AngleAxisf(0.5f * time + float(i), Vec3f::UnitY()));
    list.boxes.push_back({Vec3f(-4.5f + float(column), half.y(), 5.0f + 0.8f * float(row)), half, turn,
                          kPalette[(i + 3) % 6]});
  }
  return list;
}

render::Overlay bench_overlay(double t, double duration) {
  render::Overlay overlay;
  overlay.title = "Benchmark: 300 spheres, 100 boxes, 400 arrows";
  overlay.captions = {{"Every frame is drawn, captioned and encoded in process.", 1.0f}};
  char clock[32];
  std::snprintf(clock, sizeof clock, "t = %.2f s", t);
  overlay.clock = clock;
  overlay.playback = "real time";
  overlay.legend = {{kNormal, "contact normal", 0, false}, {kVelocity, "velocity (1 m/s)", 50.0f, false}};
  overlay.labels = {{render::Vec2f(640, 300), "J = 2.41 N\u00b7s", kNormal, {}}};
  render::Plot energy{.title = "kinetic energy", .unit = "J", .x_end = float(duration), .y_min = 0, .y_max = 0,
                      .series = {{.colour = {0.90f, 0.62f, 0.00f}, .points = {}}}};
  for (double s = 0; s <= t; s += 1.0 / 30) energy.series[0].points.push_back(render::Vec2f(float(s), float(10 + 5 * std::sin(3 * s))));
  overlay.plots.push_back(energy);
  return overlay;
}

}  // namespace impulse::bench
