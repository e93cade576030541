// Which impulse the "impulse" label writes ([overlay] label): the frame's overlay draws it, the
// take keeps its contact when no contact marks are drawn, the poster looks for its largest.
#pragma once
#include "demos/scene/scene.h"
#include "physics/body.h"
#include "physics/step_record.h"

#include <vector>

namespace impulse::demos {

// The contact and body whose normal impulse the "impulse" label writes: the first largest on a
// moving body (on `label_body` only, unless it is -1). Null when no contact pushes.
struct LabelledImpulse {
  const physics::ContactRecord* contact = nullptr;
  int body = -1;
};
LabelledImpulse labelled_impulse(const std::vector<physics::ContactRecord>& contacts,
                                 const std::vector<physics::Body>& bodies, int label_body);
int label_body(const Scene& scene);  // [overlay] label_body's index, -1 for any

}  // namespace impulse::demos
