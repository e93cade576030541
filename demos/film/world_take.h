// One world of a scene, stepped once from its start to the scene's end, and sampled at each video
// frame's moment for the film (film.h). Only the steps not yet sampled are kept (about
// PlaybackTimeline::lookahead() of them), so memory does not grow with the scene's length; what
// the film keeps is one FrameSample a frame.
#pragma once
#include "demos/film/contact_hold.h"
#include "demos/film/impact_numbers.h"
#include "demos/film/plot_recorder.h"
#include "demos/film/scene_draw_list.h"
#include "demos/scene/scene.h"
#include "demos/film/take_summary.h"
#include "physics/world.h"

#include <cstdint>
#include <deque>
#include <vector>

namespace impulse::demos {

// One world at one frame.
struct FrameSample {
  std::vector<BodyPose> poses;             // between the two steps around the frame's moment
  std::vector<physics::Vec3> velocities;   // of each body after the last step taken
  std::vector<physics::Vec3> angular_velocities;  // likewise
  std::vector<char> awake;                 // of each body after the last step taken
  std::vector<physics::ContactRecord> contacts;  // held on screen (only the label's, if no marks are drawn)
  int64_t plotted_steps = 0;               // steps the plots show
  ImpactNumbers impact;                    // the latest impact at or before the frame ([overlay] equation)
};

class WorldTake {
 public:
  explicit WorldTake(const Scene& scene);  // `scene` must outlive the take

  bool finished() const;  // stepped to the scene's duration
  double time() const { return world_.time(); }
  void step();            // one step; its impacts go to summary().impact_times

  // The frame at simulated `time` (frames in order, each at or after the one before): takes the
  // steps up to it. `video_time` is the frame's moment in the video (the contacts' hold counts it).
  void sample(double time, double video_time, FrameSample& sample);

  const TakeSummary& summary() const { return summary_; }
  // FNV-1a over the bits of every body's position, orientation and velocities after each step
  // taken: two takes that moved alike, step for step, have the same.
  uint64_t motion_hash() const { return motion_hash_; }
  std::vector<CheckResult> check_results() const { return checks_.results(); }  // the scene's [[check]]s
  const PlotRecorder& plots() const { return plots_; }
  // The bodies as built (shapes, names, masses; their motion is in the samples) and the joints.
  const std::vector<physics::Body>& bodies() const { return bodies_; }
  const std::vector<physics::Joint>& joints() const { return world_.joints(); }

 private:
  struct Step {
    double time = 0;
    std::vector<BodyPose> poses;
    std::vector<physics::Vec3> velocities, angular_velocities;
    std::vector<char> awake;
    std::vector<physics::ContactRecord> contacts;
  };
  void keep_label_candidate(std::vector<physics::ContactRecord>& contacts) const;
  struct Motion {  // of a body just before a step: eq. 13's numbers
    physics::Vec3 position, velocity, angular_velocity;
    physics::Mat3 inverse_inertia;  // world
  };
  void note_impact(const std::vector<Motion>& before);

  const Scene& scene_;
  physics::World world_;
  std::vector<physics::Body> bodies_;
  bool contacts_drawn_ = false;
  TakeSummary summary_;
  CheckWatch checks_;
  PlotRecorder plots_;
  std::vector<ImpulsePeak> impulse_peaks_;  // each step's largest impulse, for the arrow scale
  double weight_impulse_ = 0;                // N s: every moving body's weight over a step, the most a load presses
  std::deque<Step> pending_;  // stepped, not yet taken by a frame
  ContactHold hold_;
  int64_t steps_taken_ = 0;
  double taken_time_ = 0;
  std::vector<BodyPose> before_, after_;
  std::vector<physics::Vec3> velocities_, angular_velocities_;
  std::vector<char> awake_;
  std::vector<ImpactNumbers> impacts_;  // for eq. 8 on screen, in time order
  size_t impacts_shown_ = 0;            // those at or before the last sample
  uint64_t motion_hash_ = 0xcbf29ce484222325ull;
};

}  // namespace impulse::demos
