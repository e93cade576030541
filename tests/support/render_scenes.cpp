#include "tests/support/render_scenes.h"

namespace impulse::testing {

using render::Quatf;
using render::Vec3f;

render::DrawList bodies_scene() {
  render::DrawList list;
  list.camera.position = {0.5f, 2.2f, 6.0f};
  list.camera.target = {0.3f, 0.7f, 0.0f};
  list.camera.fov_y_degrees = 45.0f;
  const Quatf spin(Eigen::AngleAxisf(0.6f, Vec3f(0.3f, 1.0f, 0.1f).normalized()));
  list.spheres.push_back({Vec3f(-1.4f, 1.5f, 0.0f), 0.45f, spin, {0.90f, 0.62f, 0.00f}});
  list.spheres.push_back({Vec3f(0.1f, 0.35f, 0.6f), 0.35f, spin, {0.34f, 0.71f, 0.91f}, true, true});
  list.spheres.push_back({Vec3f(2.4f, 0.5f, -1.0f), 0.5f, Quatf::Identity(), {0.00f, 0.62f, 0.45f}});
  list.boxes.push_back({Vec3f(1.2f, 0.4f, 0.2f), Vec3f(0.4f, 0.4f, 0.4f), Quatf(Eigen::AngleAxisf(0.5f, Vec3f::UnitY())),
                        {0.80f, 0.47f, 0.65f}, true});
  list.boxes.push_back({Vec3f(-0.3f, 1.6f, -0.8f), Vec3f(0.5f, 0.2f, 0.3f),
                        Quatf(Eigen::AngleAxisf(0.7f, Vec3f(1.0f, 0.5f, 0.0f).normalized())), {0.00f, 0.45f, 0.70f}});
  const Vec3f contact(0.1f, 0.0f, 0.6f);
  list.arrows.push_back({contact, Vec3f(0.0f, 1.2f, 0.0f), {0.00f, 0.45f, 0.70f}, 3});   // impulse
  list.arrows.push_back({contact, Vec3f(0.0f, 0.6f, 0.0f), {0.84f, 0.37f, 0.00f}, 2});   // normal
  list.arrows.push_back({contact, Vec3f(0.5f, 0.0f, 0.0f), {0.80f, 0.47f, 0.65f}, 1});   // friction
  list.arrows.push_back({Vec3f(-1.4f, 1.5f, 0.0f), Vec3f(0.0f, -0.9f, 0.3f), {0.2f, 0.2f, 0.2f}, 0});  // velocity
  list.points.push_back({contact, {0.0f, 0.0f, 0.0f}, 4.0f});
  list.points.push_back({Vec3f(1.2f, 0.0f, 0.2f), {0.0f, 0.0f, 0.0f}, 4.0f});
  return list;
}

render::Overlay lecture_overlay() {
  render::Overlay overlay;
  overlay.title = "Golden: impulse and friction";
  overlay.captions = {{"The blue arrow is the impulse.", 1.0f}};
  overlay.clock = "t = 1.25 s";
  overlay.playback = "slow motion \u00d70.20";
  overlay.playback_highlight = true;
  overlay.legend = {{{0.0f, 0.0f, 0.0f}, "contact point", 0.0f, true},
                    {{0.00f, 0.45f, 0.70f}, "normal impulse: 1 N\u00b7s", 40.0f, false}};
  overlay.labels = {{render::Vec2f(170.0f, 90.0f), "J = 2.41 N\u00b7s", {0.00f, 0.45f, 0.70f}, {}}};
  render::Plot energy{.title = "kinetic energy", .unit = "J", .x_end = 2.0f, .y_min = 0.0f, .y_max = 12.0f,
                      .series = {{.colour = {0.90f, 0.62f, 0.00f}, .points = {}}}};
  for (int i = 0; i <= 25; ++i) energy.series[0].points.push_back(render::Vec2f(0.05f * i, 10.0f - 0.3f * i + (i % 5)));
  overlay.plots = {energy};
  return overlay;
}

}  // namespace impulse::testing
