#include "demos/scene_preview.h"

#include "demos/plot_recorder.h"
#include "demos/render_scene.h"

#include <algorithm>

namespace impulse::demos {

namespace {

bool needs_preview(const Scene& scene) {
  const DrawOptions& draw = scene.draw;
  const bool auto_impulse = (draw.impulses || draw.friction) && draw.impulse_scale <= 0;
  const bool auto_velocity = draw.velocities && draw.velocity_scale <= 0;
  return scene.playback.slow_motion_impulse > 0 || auto_impulse || auto_velocity || !scene.overlay.plots.empty() ||
         scene.overlay.label == "impulse";  // the label skips impulses negligible beside the largest
}

}  // namespace

ScenePreview preview_scene(const Scene& scene) {
  ScenePreview preview;
  if (!needs_preview(scene)) return preview;
  physics::World world = build_world(scene);
  const auto& bodies = world.bodies();
  PlotRecorder plots(scene.overlay.plots, plotted_body(bodies, scene.overlay.plot_body));
  const double threshold = scene.playback.slow_motion_impulse;
  while (world.time() < scene.duration + 0.5 * scene.world.time_step) {
    world.step();
    const physics::StepRecord& record = world.record();
    bool impact = false;
    for (const physics::ContactRecord& contact : record.contacts) {
      const bool moving = (contact.body_a >= 0 && !bodies[contact.body_a].is_static()) ||
                          (contact.body_b >= 0 && !bodies[contact.body_b].is_static());
      if (!moving) continue;
      preview.largest_impulse =
          std::max({preview.largest_impulse, double(contact.normal_impulse), double(contact.tangent_impulse.norm())});
      if (threshold > 0 && contact.normal_impulse >= threshold) impact = true;
    }
    if (impact) preview.impact_times.push_back(record.time);
    for (const physics::Body& body : bodies)
      if (!body.is_static()) preview.largest_speed = std::max(preview.largest_speed, double(body.velocity.norm()));
    plots.add_step(record, bodies);
  }
  preview.plot_maxima = plots.maxima();
  return preview;
}

}  // namespace impulse::demos
