// What each frame of a scene shows. The constructor steps the world once, to the scene's end,
// sampling it at each frame's moment (world_take.h): the playback timeline (slow motion around
// impacts), held contacts and the plots' progress. Then next() turns the samples into plain data,
// a DrawList and an Overlay per frame, with the arrow scales and plot axes the whole run fixed;
// it can run on a thread of its own, ahead of drawing.
//
// Memory: one FrameSample a frame (poses, velocities and sleep of every body, the contacts shown),
// about 80 bytes a body a frame; the 1000-box heap's 12 s (361 frames) about 30 MB.
#pragma once
#include "demos/film/camera_path.h"
#include "demos/film/frame_overlay.h"
#include "demos/film/marks.h"
#include "demos/film/playback_timeline.h"
#include "demos/film/scene_draw_list.h"
#include "demos/scene/scene.h"
#include "demos/film/world_take.h"
#include "render/draw_list.h"
#include "render/overlay.h"

#include <memory>
#include <optional>
#include <vector>

namespace impulse::demos {

// Which pictures a film gives, in order of simulated time: the video's frames, and stills at
// chosen moments between them (for `impulse verify` and `render --at`), which are no part of the
// video. A still shows its exact moment whatever the frame rate; what is held on screen for some
// seconds of video (contacts) is counted as the video would count it.
struct Shots {
  bool video_frames = true;
  std::vector<double> stills;      // s of simulated time, 0 .. the duration
  bool stills_at_impacts = false;  // also one at each impact that slows the video (the ms after it)
};

struct ScenePicture {
  render::DrawList draw_list;
  render::Overlay overlay;
  int frame = -1;                   // the video's frame number; -1: a still
  double time = 0;                  // simulated s shown
  std::vector<BodyPose> poses;      // every body's, for a still
};

// What the films of a comparison share, so that their arrows' and plots' lengths compare: the
// largest impulse, speed and plotted values of any, the extent every pane's bodies move through, and
// every impact (in order).
TakeSummary shared_summary(const std::vector<const TakeSummary*>& summaries);

class SceneFilm {
 public:
  // Simulates the whole scene. `scene` must outlive the film.
  SceneFilm(const Scene& scene, int width, int height, const Shots& shots = {});
  // Several scenes, each simulated once, their worlds stepped side by side and every film shown at
  // the same moments: the first scene's playback, duration and frame rate, slowed around an impact
  // of any of them, with one arrow scale and plot range for all (a comparison, film.h).
  static std::vector<std::unique_ptr<SceneFilm>> together(const std::vector<const Scene*>& scenes, int width,
                                                          int height, const Shots& shots = {});

  int frame_count() const { return frame_count_; }  // the video's
  int picture_count() const { return picture_count_; }  // what next() gives: the frames (if shot) and stills
  int next_picture() const { return picture_; }
  // Seconds into the video at which simulated time `time` is first shown (slow motion included);
  // the video's length for a time past the last frame.
  double video_time_of(double time) const;
  // The largest impulse the "impulse" label writes in any frame (without that label, the largest
  // impulse arrow on a moving body), and the middle one of the frames in a row that show it;
  // frame -1 when none shows.
  struct LabelledPeak {
    int frame = -1;
    double impulse = 0;
  };
  LabelledPeak labelled_peak() const { return labelled_peak_; }
  // The frame that teaches, for a poster: the first frame showing [playback] poster's moment when
  // it is set; else `peak`'s frame (the run's largest labelled impulse); else a quarter second of
  // video after the first impact that slows the video; else the middle frame. A frame where a
  // caption fades in or out gives way to the nearest one where none does.
  int poster_frame(const LabelledPeak& peak) const;
  int poster_frame() const { return poster_frame(labelled_peak_); }
  const std::vector<double>& impact_times() const { return impact_times_; }  // s: those that slow the video
  std::vector<CheckResult> check_results() const { return take_.check_results(); }
  uint64_t motion_hash() const { return take_.motion_hash(); }  // WorldTake::motion_hash
  // The bodies as built: names, shapes (their motion is in the pictures).
  const std::vector<physics::Body>& bodies() const { return take_.bodies(); }
  // Fills `picture` with the next picture (from 0 up to picture_count() - 1).
  void next(ScenePicture& picture);

 private:
  struct Moment {
    double time = 0;   // simulated s shown
    double speed = 1;  // playback factor then
    bool slow_motion = false;
    int frame = -1;     // the video's frame number; -1: a still
    bool drawn = true;  // a picture next() gives (a frame not shot only moves the camera on)
  };
  explicit SceneFilm(const Scene& scene);   // not yet shot
  static void shoot(const std::vector<SceneFilm*>& films, const Shots& shots);
  void add_moment(const Moment& moment, double video_time);
  // Once shot: the arrow scales and the overlay's axes that `summary` (the run's, or the largest of
  // films shown together) fixes.
  void develop(int width, int height, const TakeSummary& summary);
  // Where the moving bodies go on screen over the film (render::Overlay::body_paths).
  std::vector<render::ScreenBox> body_paths(int width, int height) const;

  const Scene& scene_;
  WorldTake take_;
  std::vector<Moment> moments_;
  std::vector<FrameSample> samples_;  // one per frame, released as next() uses it
  ArrowScales scales_;
  std::optional<FrameOverlay> overlay_maker_;
  std::vector<double> impact_times_;
  LabelledPeak labelled_peak_;
  CameraPath camera_path_;
  std::vector<physics::Body> bodies_;  // the take's, moved to each frame's sample
  size_t moment_ = 0;  // the next one next() looks at
  int frame_count_ = 0, picture_count_ = 0, picture_ = 0;
};

}  // namespace impulse::demos
