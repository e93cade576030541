#include "demos/film/scene_film.h"

#include <algorithm>
#include <cmath>

namespace impulse::demos {

SceneFilm::SceneFilm(const Scene& scene, int width, int height)
    : scene_(scene), take_(scene), camera_path_(scene), bodies_(take_.bodies()) {
  shoot(width, height);
  const TakeSummary summary = take_.summary();
  impact_times_ = summary.impact_times;
  scales_ = arrow_scales(scene, summary);
  overlay_maker_.emplace(scene, summary, scales_, width, height);
}

// Steps the world to its end, and samples each frame as soon as the world is far enough past its
// moment that no impact to come can change the playback speed there.
void SceneFilm::shoot(int /*width*/, int /*height*/) {
  PlaybackTimeline timeline(scene_.playback, scene_.duration, scene_.video.fps);
  size_t impacts_known = 0;
  double time = 0;  // the next frame's moment
  bool more = true;
  while (more) {
    while (!take_.finished() && take_.time() < time + timeline.lookahead()) {
      take_.step();
      const std::vector<double>& impacts = take_.summary().impact_times;
      for (; impacts_known < impacts.size(); ++impacts_known) timeline.add_impact(impacts[impacts_known]);
    }
    const double video_time = double(moments_.size()) / scene_.video.fps;
    moments_.push_back({time, timeline.speed_at(time), timeline.slow_motion_at(time)});
    take_.sample(time, video_time, samples_.emplace_back());
    const bool shown = timeline.shows(time);
    time = timeline.next_frame_time(time);
    more = shown && timeline.shows(time) && moments_.size() < 10'000'000;
  }
  while (!take_.finished()) take_.step();  // the summary covers the whole duration
}

double SceneFilm::video_time_of(double time) const {
  const auto shown = std::find_if(moments_.begin(), moments_.end(), [&](const Moment& m) { return m.time >= time - 1e-9; });
  return double(shown - moments_.begin()) / scene_.video.fps;
}

int SceneFilm::poster_frame() const {
  if (impact_times_.empty()) return frame_count() / 2;
  const int after = int(std::lround((video_time_of(impact_times_.front()) + 0.25) * scene_.video.fps));
  return std::clamp(after, 0, frame_count() - 1);
}

void SceneFilm::next(ScenePicture& picture) {
  const Moment& moment = moments_[frame_];
  FrameSample& sample = samples_[frame_];
  for (size_t i = 0; i < bodies_.size(); ++i) {
    bodies_[i].velocity = sample.velocities[i];
    bodies_[i].awake = sample.awake[i] != 0;
  }
  const int followed = camera_path_.followed_body();
  FrameState state;
  state.time = moment.time;
  state.speed = moment.speed;
  state.slow_motion = moment.slow_motion;
  state.bodies = &bodies_;
  state.poses = &sample.poses;
  state.contacts = &sample.contacts;
  state.plotted_steps = sample.plotted_steps;
  state.camera = camera_path_.at(moment.time, followed >= 0 ? sample.poses[followed].position : physics::Vec3::Zero());

  picture.draw_list =
      scene_draw_list(scene_, bodies_, sample.poses, take_.joints(), sample.contacts, scales_, state.camera);
  overlay_maker_->make(state, take_.plots(), picture.overlay);
  sample = FrameSample{};  // its memory is no longer needed
  ++frame_;
}

}  // namespace impulse::demos
