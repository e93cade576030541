// Keeps contacts on screen a little after their step. An impact lasts one physics step (1/60 s),
// less than a frame: without a hold its arrows would flash by or fall between frames. For each
// pair of bodies this keeps an impact's step for `hold` seconds of video, unless a step with at
// least half its total normal impulse comes (so resting and rolling contacts show their latest).
#pragma once
#include "physics/step_record.h"

#include <map>
#include <utility>
#include <vector>

namespace impulse::demos {

class ContactHold {
 public:
  explicit ContactHold(double hold_seconds) : hold_(hold_seconds) {}

  void add_step(const std::vector<physics::ContactRecord>& contacts, double video_time);
  // The contacts to draw at `video_time` (after forgetting those held too long).
  const std::vector<physics::ContactRecord>& shown(double video_time);

 private:
  struct Held {
    double video_time = 0;
    double total_impulse = 0;
    std::vector<physics::ContactRecord> contacts;
  };
  double hold_;
  std::map<std::pair<int, int>, Held> pairs_;
  std::map<std::pair<int, int>, Held> step_;  // scratch: this step's contacts by pair
  std::vector<physics::ContactRecord> shown_;
};

}  // namespace impulse::demos
