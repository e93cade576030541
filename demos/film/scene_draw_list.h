// What a frame of a scene shows, as a render::DrawList: the bodies where they are at the frame's
// moment, and the marks (contact points, normals, impulses, velocities) the scene switches on.
#pragma once
#include "demos/film/marks.h"
#include "demos/scene/scene.h"
#include "physics/world.h"
#include "render/draw_list.h"

#include <vector>

namespace impulse::demos {

struct BodyPose {
  physics::Vec3 position = physics::Vec3::Zero();
  physics::Quat orientation = physics::Quat::Identity();
};

std::vector<BodyPose> poses_of(const std::vector<physics::Body>& bodies);
// Between two steps' poses: positions linearly, orientations by slerp; weight 0 gives `from`.
void interpolate(const std::vector<BodyPose>& from, const std::vector<BodyPose>& to, double weight,
                 std::vector<BodyPose>& out);

// The arrow of the impulse on `body` (a moving body of the contact), from the contact point.
render::Vec3f impulse_on(const physics::ContactRecord& contact, int body);

// Joints are drawn as grey lines (rods, ropes) and dots (ball and hinge pivots) where the poses
// put their anchors. A horizontal plane is the renderer's ground; any other (an incline) a thin
// slab in its colour, its top face in the plane, about the point nearest the camera's target.
render::DrawList scene_draw_list(const Scene& scene, const std::vector<physics::Body>& bodies,
                                 const std::vector<BodyPose>& poses, const std::vector<physics::Joint>& joints,
                                 const std::vector<physics::ContactRecord>& contacts, const ArrowScales& scales,
                                 const render::Camera& camera);

}  // namespace impulse::demos
