#include "demos/film/scene_film.h"

#include <algorithm>
#include <cmath>

namespace impulse::demos {

SceneFilm::SceneFilm(const Scene& scene) : scene_(scene), take_(scene), camera_path_(scene), bodies_(take_.bodies()) {}

SceneFilm::SceneFilm(const Scene& scene, int width, int height) : SceneFilm(scene) {
  shoot({this});
  develop(width, height, take_.summary());
}

std::vector<std::unique_ptr<SceneFilm>> SceneFilm::together(const std::vector<const Scene*>& scenes, int width,
                                                            int height) {
  std::vector<std::unique_ptr<SceneFilm>> films;
  std::vector<SceneFilm*> shot;
  for (const Scene* scene : scenes) shot.push_back(films.emplace_back(new SceneFilm(*scene)).get());
  if (shot.empty()) return films;
  shoot(shot);
  // One scale for the arrows and the plots of every film, so that their lengths compare.
  TakeSummary largest;
  for (const SceneFilm* film : shot) {
    const TakeSummary& summary = film->take_.summary();
    largest.largest_impulse = std::max(largest.largest_impulse, summary.largest_impulse);
    largest.impulse_to_fit = std::max(largest.impulse_to_fit, summary.impulse_to_fit);
    largest.largest_speed = std::max(largest.largest_speed, summary.largest_speed);
    largest.plot_maxima.resize(std::max(largest.plot_maxima.size(), summary.plot_maxima.size()), 0.0);
    for (size_t k = 0; k < summary.plot_maxima.size(); ++k)
      largest.plot_maxima[k] = std::max(largest.plot_maxima[k], summary.plot_maxima[k]);
  }
  for (SceneFilm* film : shot) {
    TakeSummary summary = film->take_.summary();
    summary.largest_impulse = largest.largest_impulse;
    summary.impulse_to_fit = largest.impulse_to_fit;
    summary.largest_speed = largest.largest_speed;
    summary.plot_maxima.assign(largest.plot_maxima.begin(), largest.plot_maxima.begin() + summary.plot_maxima.size());
    film->develop(width, height, summary);
  }
  return films;
}

void SceneFilm::develop(int width, int height, const TakeSummary& summary) {
  impact_times_ = summary.impact_times;
  scales_ = arrow_scales(scene_, summary);
  overlay_maker_.emplace(scene_, summary, scales_, width, height);
  std::vector<const ImpactNumbers*> impacts;
  for (const FrameSample& sample : samples_) impacts.push_back(&sample.impact);
  overlay_maker_->prepare(impacts);
}

// Steps the worlds to their end, and samples each frame as soon as every world is far enough past
// its moment that no impact to come can change the playback speed there.
void SceneFilm::shoot(const std::vector<SceneFilm*>& films) {
  const Scene& first = films.front()->scene_;
  PlaybackTimeline timeline(first.playback, first.duration, first.video.fps);
  std::vector<size_t> impacts_known(films.size(), 0);
  double time = 0;  // the next frame's moment
  bool more = true;
  while (more) {
    for (size_t i = 0; i < films.size(); ++i) {
      WorldTake& take = films[i]->take_;
      while (!take.finished() && take.time() < time + timeline.lookahead()) {
        take.step();
        const std::vector<double>& impacts = take.summary().impact_times;
        for (; impacts_known[i] < impacts.size(); ++impacts_known[i]) timeline.add_impact(impacts[impacts_known[i]]);
      }
    }
    const double video_time = double(films.front()->moments_.size()) / first.video.fps;
    const Moment moment{time, timeline.speed_at(time), timeline.slow_motion_at(time)};
    for (SceneFilm* film : films) {
      film->moments_.push_back(moment);
      film->take_.sample(time, video_time, film->samples_.emplace_back());
    }
    const bool shown = timeline.shows(time);
    time = timeline.next_frame_time(time);
    more = shown && timeline.shows(time) && films.front()->moments_.size() < 10'000'000;
  }
  for (SceneFilm* film : films)
    while (!film->take_.finished()) film->take_.step();  // the summary covers the whole duration
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
  state.impact = &sample.impact;
  state.camera = camera_path_.at(moment.time, followed >= 0 ? sample.poses[followed].position : physics::Vec3::Zero());

  picture.draw_list =
      scene_draw_list(scene_, bodies_, sample.poses, take_.joints(), sample.contacts, scales_, state.camera);
  overlay_maker_->make(state, take_.plots(), picture.overlay);
  sample = FrameSample{};  // its memory is no longer needed
  ++frame_;
}

}  // namespace impulse::demos
