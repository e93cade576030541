#include "demos/scene_film.h"

#include "demos/render_scene.h"

#include <algorithm>

namespace impulse::demos {

SceneFilm::SceneFilm(const Scene& scene, int width, int height)
    : scene_(scene),
      fps_(scene.video.fps),
      preview_(preview_scene(scene)),
      scales_(arrow_scales(scene, preview_)),
      timeline_(scene.playback, preview_.impact_times, scene.duration, scene.video.fps),
      world_(build_world(scene)),
      plots_(scene.overlay.plots, plotted_body(world_.bodies(), scene.overlay.plot_body)),
      hold_(scene.draw.contact_hold),
      camera_path_(scene),
      overlay_maker_(scene, preview_, scales_, width, height),
      before_(poses_of(world_.bodies())),
      after_(before_) {}

void SceneFilm::next(ScenePicture& picture) {
  const double video_time = double(frame_) / fps_;
  // Step until the world is at or past this frame's moment; draw the bodies in between.
  while (world_.time() < time_ - 1e-9) {
    before_.swap(after_);
    world_.step();
    const physics::StepRecord& record = world_.record();
    after_ = poses_of(world_.bodies());
    hold_.add_step(record, video_time);
    plots_.add_step(record, world_.bodies());
  }
  const double step = scene_.world.time_step;
  const double weight = world_.step_count() == 0 ? 1.0 : std::clamp(1.0 - (world_.time() - time_) / step, 0.0, 1.0);
  interpolate(before_, after_, weight, shown_);

  const int followed = camera_path_.followed_body();
  FrameState state;
  state.time = time_;
  state.speed = timeline_.speed_at(time_);
  state.slow_motion = timeline_.slow_motion_at(time_);
  state.bodies = &world_.bodies();
  state.poses = &shown_;
  state.contacts = &hold_.shown(video_time);
  state.camera = camera_path_.at(time_, followed >= 0 ? shown_[followed].position : physics::Vec3::Zero());

  picture.draw_list = scene_draw_list(scene_, world_.bodies(), shown_, world_.joints(), *state.contacts, scales_, state.camera);
  overlay_maker_.make(state, plots_, picture.overlay);
  time_ = timeline_.next_frame_time(time_);
  ++frame_;
}

}  // namespace impulse::demos
