#include "demos/film/contact_hold.h"

namespace impulse::demos {

void ContactHold::add_step(const std::vector<physics::ContactRecord>& contacts, double video_time) {
  step_.clear();
  for (const physics::ContactRecord& contact : contacts) {
    Held& held = step_[{contact.body_a, contact.body_b}];
    held.video_time = video_time;
    held.total_impulse += contact.normal_impulse;
    held.contacts.push_back(contact);
  }
  for (auto& [pair, now] : step_) {
    auto found = pairs_.find(pair);
    const bool replace = found == pairs_.end() || now.total_impulse >= 0.5 * found->second.total_impulse ||
                         video_time - found->second.video_time > hold_ || hold_ <= 0;
    if (replace) pairs_[pair] = std::move(now);
  }
}

const std::vector<physics::ContactRecord>& ContactHold::shown(double video_time) {
  shown_.clear();
  for (auto it = pairs_.begin(); it != pairs_.end();) {
    // A pair not touched this step (hold 0) or beyond the hold is forgotten.
    if (video_time - it->second.video_time > hold_ + 1e-9) {
      it = pairs_.erase(it);
      continue;
    }
    shown_.insert(shown_.end(), it->second.contacts.begin(), it->second.contacts.end());
    ++it;
  }
  return shown_;
}

}  // namespace impulse::demos
