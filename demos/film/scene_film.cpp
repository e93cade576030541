#include "demos/film/scene_film.h"

#include "demos/film/body_boxes.h"
#include "demos/film/impulse_label.h"
#include "demos/film/moments.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "demos/film/captions.h"

namespace impulse::demos {

SceneFilm::SceneFilm(const Scene& scene) : scene_(scene), take_(scene), camera_path_(scene), bodies_(take_.bodies()) {}

SceneFilm::SceneFilm(const Scene& scene, int width, int height, const Shots& shots) : SceneFilm(scene) {
  shoot({this}, shots);
  develop(width, height, take_.summary());
}

TakeSummary shared_summary(const std::vector<const TakeSummary*>& summaries) {
  TakeSummary largest;
  for (const TakeSummary* summary : summaries) {
    largest.impact_times.insert(largest.impact_times.end(), summary->impact_times.begin(), summary->impact_times.end());
    largest.largest_impulse = std::max(largest.largest_impulse, summary->largest_impulse);
    largest.impulse_to_fit = std::max(largest.impulse_to_fit, summary->impulse_to_fit);
    largest.largest_speed = std::max(largest.largest_speed, summary->largest_speed);
    largest.someone_sleeps = largest.someone_sleeps || summary->someone_sleeps;
    largest.moving_extent.extend(summary->moving_extent);  // the panes share one camera
    largest.plot_maxima.resize(std::max(largest.plot_maxima.size(), summary->plot_maxima.size()), 0.0);
    for (size_t k = 0; k < summary->plot_maxima.size(); ++k)
      largest.plot_maxima[k] = std::max(largest.plot_maxima[k], summary->plot_maxima[k]);
  }
  std::sort(largest.impact_times.begin(), largest.impact_times.end());
  return largest;
}

std::vector<std::unique_ptr<SceneFilm>> SceneFilm::together(const std::vector<const Scene*>& scenes, int width,
                                                            int height, const Shots& shots) {
  std::vector<std::unique_ptr<SceneFilm>> films;
  std::vector<SceneFilm*> shot;
  for (const Scene* scene : scenes) shot.push_back(films.emplace_back(new SceneFilm(*scene)).get());
  if (shot.empty()) return films;
  shoot(shot, shots);
  std::vector<const TakeSummary*> summaries;
  for (const SceneFilm* film : shot) summaries.push_back(&film->take_.summary());
  const TakeSummary largest = shared_summary(summaries);
  for (SceneFilm* film : shot) {
    TakeSummary summary = film->take_.summary();
    summary.largest_impulse = largest.largest_impulse;
    summary.impulse_to_fit = largest.impulse_to_fit;
    summary.largest_speed = largest.largest_speed;
    summary.someone_sleeps = largest.someone_sleeps;
    summary.moving_extent = largest.moving_extent;
    summary.plot_maxima.assign(largest.plot_maxima.begin(), largest.plot_maxima.begin() + summary.plot_maxima.size());
    film->develop(width, height, summary);
  }
  return films;
}

void SceneFilm::develop(int width, int height, const TakeSummary& summary) {
  impact_times_ = summary.impact_times;
  labelled_peak_ = {};
  const bool label_written = scene_.overlay.label == "impulse";
  if (label_written || scene_.draw.impulses) {
    const int body = label_written ? label_body(scene_) : -1;
    int last = -1;  // the last frame that still shows the peak (the hold keeps an impact on screen)
    for (size_t i = 0; i < samples_.size(); ++i) {
      if (moments_[i].frame < 0) continue;  // a still, not a frame of the video
      const std::vector<physics::ContactRecord> marked = marked_contacts(samples_[i].contacts, scene_.draw.marked_pairs);
      const LabelledImpulse labelled = labelled_impulse(marked, bodies_, body);
      // As the label: 0.005 N s and more (frame_overlay.cpp).
      if (labelled.contact == nullptr || labelled.contact->normal_impulse < 0.005) continue;
      if (labelled.contact->normal_impulse > labelled_peak_.impulse) {
        labelled_peak_ = {moments_[i].frame, labelled.contact->normal_impulse};
        last = moments_[i].frame;
      } else if (labelled.contact->normal_impulse == labelled_peak_.impulse && last == moments_[i].frame - 1) {
        last = moments_[i].frame;
      }
    }
    // The middle of the frames showing it: the impact's marks, and what follows from it (its
    // equation panel, the bodies parting), are on screen together.
    if (labelled_peak_.frame >= 0) labelled_peak_.frame = (labelled_peak_.frame + last) / 2;
  }
  if (scene_.camera_motion.fit) camera_path_.fit(summary.moving_extent, double(width) / height);
  scales_ = arrow_scales(scene_, summary);
  overlay_maker_.emplace(scene_, summary, scales_, width, height);
  overlay_maker_->set_body_paths(body_paths(width, height));
  std::vector<const ImpactNumbers*> impacts;
  for (const FrameSample& sample : samples_) impacts.push_back(&sample.impact);
  overlay_maker_->prepare(impacts);
}

namespace {

// An impact's still: the first whole millisecond at or after it, so that its name (t_0.984.png)
// is its moment and the step of the impact is shown.
double still_after(double impact) { return std::ceil(impact * 1000 - 1e-6) / 1000; }

}  // namespace

// Every moment's bodies on screen, the camera moving on as next() will move it; and the fixed
// pivots of joints (what a pendulum hangs from is part of what it shows).
std::vector<render::ScreenBox> SceneFilm::body_paths(int width, int height) const {
  BodyPaths paths(width, height);
  CameraPath camera_path = camera_path_;
  const int followed = camera_path.followed_body();
  const float pivot = 12.0f * float(height) / 720;  // pixels round a pivot
  std::vector<render::OverlayBody> boxes;
  for (size_t i = 0; i < moments_.size(); ++i) {
    const std::vector<BodyPose>& poses = samples_[i].poses;
    const render::Camera camera = camera_path.at(moments_[i].time, followed >= 0 ? poses[followed].position : physics::Vec3::Zero());
    const render::CameraView view = render::make_camera_view(camera, width, height);
    boxes.clear();
    add_body_boxes(bodies_, poses, view, boxes);
    for (const render::OverlayBody& body : boxes)
      if (body.moving) paths.add(body.box);
    for (const physics::Joint& joint : take_.joints())
      for (const auto& [body, anchor] : {std::pair{joint.body_a, joint.local_anchor_a}, std::pair{joint.body_b, joint.local_anchor_b}})
        if (body == physics::kWorld)
          if (const auto pixel = view.to_pixels(anchor.cast<float>()))
            paths.add({pixel->x() - pivot, pixel->y() - pivot, 2 * pivot, 2 * pivot});
  }
  return paths.boxes();
}

void SceneFilm::add_moment(const Moment& moment, double video_time) {
  moments_.push_back(moment);
  take_.sample(moment.time, video_time, samples_.emplace_back());
  if (moment.frame >= 0) ++frame_count_;
  if (moment.drawn) ++picture_count_;
}

// Steps the worlds to their end, and samples each frame as soon as every world is far enough past
// its moment that no impact to come can change the playback speed there; the stills between two
// frames right after the first of them.
void SceneFilm::shoot(const std::vector<SceneFilm*>& films, const Shots& shots) {
  const Scene& first = films.front()->scene_;
  PlaybackTimeline timeline(first.playback, first.duration, first.video.fps);
  std::vector<double> stills = shots.stills;  // sorted, those still to take
  std::sort(stills.begin(), stills.end());
  std::vector<size_t> impacts_known(films.size(), 0);
  double time = 0;  // the next frame's moment
  int frame = 0;
  bool more = true;
  while (more) {
    for (size_t i = 0; i < films.size(); ++i) {
      WorldTake& take = films[i]->take_;
      while (!take.finished() && take.time() < time + timeline.lookahead()) {
        take.step();
        const std::vector<double>& impacts = take.summary().impact_times;
        for (; impacts_known[i] < impacts.size(); ++impacts_known[i]) {
          timeline.add_impact(impacts[impacts_known[i]]);
          const double still = still_after(impacts[impacts_known[i]]);
          if (shots.stills_at_impacts && !std::binary_search(stills.begin(), stills.end(), still))
            stills.insert(std::upper_bound(stills.begin(), stills.end(), still), still);
        }
      }
    }
    const double video_time = double(frame) / first.video.fps;
    const Moment moment{time, timeline.speed_at(time), timeline.slow_motion_at(time), frame++, shots.video_frames};
    for (SceneFilm* film : films) film->add_moment(moment, video_time);
    const bool shown = timeline.shows(time);
    const double next = timeline.next_frame_time(time);
    more = shown && timeline.shows(next) && frame < 10'000'000;
    // The stills before the next frame (after the last frame: the rest), each at its moment of video.
    while (!stills.empty() && stills.front() >= time - 1e-9 && stills.front() <= first.duration + 1e-9 &&
           (stills.front() < next - 1e-9 || !more)) {
      const double still = stills.front();
      if (more) {
        const Moment at{still, timeline.speed_at(still), timeline.slow_motion_at(still), -1, true};
        for (SceneFilm* film : films) film->add_moment(at, video_time + (still - time) / (next - time) / first.video.fps);
      } else {  // past the last frame: the world must be stepped up to it
        for (SceneFilm* film : films)
          while (!film->take_.finished() && film->take_.time() < still - 1e-9) film->take_.step();
        const Moment at{still, timeline.speed_at(still), timeline.slow_motion_at(still), -1, true};
        for (SceneFilm* film : films) film->add_moment(at, double(frame) / first.video.fps);
      }
      stills.erase(stills.begin());
    }
    time = next;
  }
  if (!stills.empty())
    throw std::invalid_argument("a still at t = " + moment_name(stills.front()).substr(2) + " s is past the scene's end (" +
                                moment_name(first.duration).substr(2) + " s): --at takes moments from 0 to the duration");
  for (SceneFilm* film : films)
    while (!film->take_.finished()) film->take_.step();  // the summary covers the whole duration
}

double SceneFilm::video_time_of(double time) const {
  const auto shown = std::find_if(moments_.begin(), moments_.end(),
                                  [&](const Moment& m) { return m.frame >= 0 && m.time >= time - 1e-9; });
  return double(shown == moments_.end() ? frame_count_ : shown->frame) / scene_.video.fps;
}

int SceneFilm::poster_frame(const LabelledPeak& peak) const {
  int frame = frame_count() / 2;
  if (scene_.playback.poster) {
    frame = int(std::lround(video_time_of(*scene_.playback.poster) * scene_.video.fps));
  } else if (peak.frame >= 0) {
    frame = peak.frame;
  } else if (!impact_times_.empty()) {
    frame = int(std::lround((video_time_of(impact_times_.front()) + 0.25) * scene_.video.fps));
  }
  frame = std::clamp(frame, 0, frame_count() - 1);
  std::vector<double> frame_times;  // simulated s each frame of the video shows
  for (const Moment& moment : moments_)
    if (moment.frame >= 0) frame_times.push_back(moment.time);
  const auto fading = [&](int f) {  // a caption or an [[equation]] fading in or out
    const double time = frame_times[size_t(f)];
    for (const render::Caption& caption : captions_at(scene_.captions, time))
      if (caption.opacity < 1) return true;
    for (const EquationCue& cue : scene_.equations)
      if (time >= cue.start && time < cue.end && cue_opacity(cue.start, cue.end, time) < 1) return true;
    return false;
  };
  for (int distance = 0; distance < frame_count(); ++distance)
    for (const int f : {frame + distance, frame - distance})
      if (f >= 0 && f < frame_count() && !fading(f)) return f;
  return frame;
}

void SceneFilm::next(ScenePicture& picture) {
  // Frames not shot: only the camera moves on (following is smoothed frame to frame).
  const int followed = camera_path_.followed_body();
  for (; moment_ < moments_.size() && !moments_[moment_].drawn; ++moment_) {
    const FrameSample& sample = samples_[moment_];
    camera_path_.at(moments_[moment_].time, followed >= 0 ? sample.poses[followed].position : physics::Vec3::Zero());
    samples_[moment_] = FrameSample{};
  }
  if (moment_ >= moments_.size()) throw std::logic_error("SceneFilm::next: no picture left");
  const Moment& moment = moments_[moment_];
  FrameSample& sample = samples_[moment_];
  for (size_t i = 0; i < bodies_.size(); ++i) {
    bodies_[i].velocity = sample.velocities[i];
    bodies_[i].awake = sample.awake[i] != 0;
  }
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
  state.arrows = &picture.draw_list.arrows;
  overlay_maker_->make(state, take_.plots(), picture.overlay);
  picture.frame = moment.frame;
  picture.time = moment.time;
  if (moment.frame < 0) picture.poses = sample.poses;
  sample = FrameSample{};  // its memory is no longer needed
  ++moment_;
  ++picture_;
}

}  // namespace impulse::demos
