#include "demos/film/impulse_label.h"

namespace impulse::demos {

int label_body(const Scene& scene) {
  return scene.overlay.label_body.empty() ? -1 : find_body(scene, scene.overlay.label_body);
}

LabelledImpulse labelled_impulse(const std::vector<physics::ContactRecord>& contacts,
                                 const std::vector<physics::Body>& bodies, int label_body) {
  LabelledImpulse labelled;
  double largest = 0;
  for (const physics::ContactRecord& contact : contacts) {
    for (int body : {contact.body_a, contact.body_b}) {
      const bool chosen = body >= 0 && body < int(bodies.size()) && !bodies[body].is_static() &&
                          (label_body < 0 || body == label_body);
      if (!chosen || !(contact.normal_impulse > largest)) continue;
      largest = contact.normal_impulse;
      labelled = {&contact, body};
    }
  }
  return labelled;
}

}  // namespace impulse::demos
