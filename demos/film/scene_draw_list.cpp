#include "demos/film/scene_draw_list.h"

#include "demos/film/render_types.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>

namespace impulse::demos {
namespace {

render::Vec3f to_float(const physics::Vec3& v) { return v.cast<float>(); }

bool moves(const std::vector<physics::Body>& bodies, int index) {
  return index >= 0 && index < int(bodies.size()) && !bodies[index].is_static();
}

// Where arrows overlap, the one drawn on top (render::ArrowItem::layer).
enum Layer { velocity_layer = 0, friction_layer = 1, normal_layer = 2, impulse_layer = 3 };

void add_arrow(render::DrawList& list, const render::Vec3f& origin, const render::Vec3f& direction,
               const render::Colour& colour, Layer layer) {
  if (direction.norm() > 1e-4f) list.arrows.push_back({origin, direction, colour, layer});
}

// A joint's anchor on `body` (or the fixed world point) where the body's pose puts it.
render::Vec3f anchor_point(const std::vector<BodyPose>& poses, int body, const physics::Vec3& local) {
  if (body < 0 || body >= int(poses.size())) return to_float(local);
  return to_float(poses[body].position + poses[body].orientation * local);
}

void add_joints(render::DrawList& list, const std::vector<BodyPose>& poses, const std::vector<physics::Joint>& joints) {
  for (const physics::Joint& joint : joints) {
    const render::Vec3f a = anchor_point(poses, joint.body_a, joint.local_anchor_a);
    const render::Vec3f b = anchor_point(poses, joint.body_b, joint.local_anchor_b);
    if (joint.type == physics::JointType::distance)
      list.lines.push_back({a, b, mark_colour::joint, joint.rope ? 2.0f : 3.0f});
    else
      list.points.push_back({a, mark_colour::joint, 5.0f});
    // A fixed pivot also shows as a dot, so the viewer sees where the rod hangs from.
    if (joint.body_a == physics::kWorld && joint.type == physics::JointType::distance)
      list.points.push_back({a, mark_colour::joint, 4.0f});
  }
}

// A mark's colour, faded towards white: the arrows of a resting contact beside a hit.
render::Colour faint(const render::Colour& colour) {
  constexpr float kFade = 0.6f;
  return {colour.r + (1 - colour.r) * kFade, colour.g + (1 - colour.g) * kFade, colour.b + (1 - colour.b) * kFade};
}

// A contact's dot is at most this share of the smaller body it marks, by body_size().
constexpr float kDotShare = 0.25f;

// A contact body's size (body_size()); the world (-1) has none.
float contact_body_size(const std::vector<physics::Body>& bodies, int body) {
  return body < 0 || body >= int(bodies.size()) ? INFINITY : float(body_size(bodies[body].shape));
}

// A plane other than the ground (an incline, a wall), drawn as a thin slab whose top face lies in
// it: square about the plane's point nearest the camera's target, as wide as the camera is far
// from it (no less than kSlabHalfSide), so it fills the view about the bodies it holds.
constexpr float kSlabHalfSide = 6.0f;
constexpr float kSlabHalfThickness = 0.01f;

render::BoxItem plane_slab(const physics::Shape& plane, const render::Camera& camera, const render::Colour& colour) {
  const physics::Vec3 normal = plane.normal.normalized();
  const physics::Vec3 target = camera.target.cast<physics::Real>();
  const physics::Vec3 nearest = target - (normal.dot(target) - plane.offset / plane.normal.norm()) * normal;
  const float half_side = std::max(kSlabHalfSide, (camera.position - camera.target).norm());
  render::BoxItem slab;
  slab.centre = to_float(nearest - kSlabHalfThickness * normal);
  slab.half_extents = {half_side, kSlabHalfThickness, half_side};
  slab.orientation = render::Quatf::FromTwoVectors(render::Vec3f::UnitY(), normal.cast<float>());
  slab.colour = colour;
  return slab;
}

// A shape's triangles, made once per hull or mesh and shared by every frame that draws it: the
// renderer uploads one mesh per vector. Draw lists are made on any thread, several at once, hence
// the lock; an entry whose shape is gone (its address perhaps now another's) is made again, and
// such entries are dropped whenever one is added.
template <class Surface, class Make>
std::shared_ptr<const std::vector<render::Vec3f>> kept_triangles(const std::shared_ptr<const Surface>& surface, Make make) {
  struct Made {
    std::weak_ptr<const Surface> surface;
    std::shared_ptr<const std::vector<render::Vec3f>> triangles;
  };
  static std::mutex mutex;
  static std::unordered_map<const Surface*, Made> made;
  const std::lock_guard lock(mutex);
  if (const auto found = made.find(surface.get()); found != made.end() && found->second.surface.lock() == surface)
    return found->second.triangles;
  auto triangles = std::make_shared<std::vector<render::Vec3f>>();
  make(*surface, *triangles);
  std::erase_if(made, [](const auto& entry) { return entry.second.surface.expired(); });
  made[surface.get()] = {surface, triangles};
  return triangles;
}

// A hull's faces, each fanned from its first corner, so counter-clockwise seen from outside as the face is.
std::shared_ptr<const std::vector<render::Vec3f>> hull_triangles(const std::shared_ptr<const physics::Hull>& hull) {
  return kept_triangles(hull, [](const physics::Hull& h, std::vector<render::Vec3f>& triangles) {
    for (const physics::HullFace& face : h.faces)
      for (int k = 1; k + 1 < face.count; ++k)
        for (const int corner : {h.corner_of(face, 0), h.corner_of(face, k), h.corner_of(face, k + 1)})
          triangles.push_back(to_float(h.corners[size_t(corner)]));
  });
}

// A mesh's triangles as the file gave them.
std::shared_ptr<const std::vector<render::Vec3f>> mesh_triangles(const std::shared_ptr<const physics::Mesh>& mesh) {
  return kept_triangles(mesh, [](const physics::Mesh& m, std::vector<render::Vec3f>& triangles) {
    for (const physics::MeshTriangle& triangle : m.triangles)
      for (const int corner : triangle.corners) triangles.push_back(to_float(m.vertices[size_t(corner)]));
  });
}

}  // namespace

std::vector<BodyPose> poses_of(const std::vector<physics::Body>& bodies) {
  std::vector<BodyPose> poses;
  poses.reserve(bodies.size());
  for (const physics::Body& body : bodies) poses.push_back({body.position, body.orientation});
  return poses;
}

void interpolate(const std::vector<BodyPose>& from, const std::vector<BodyPose>& to, double weight,
                 std::vector<BodyPose>& out) {
  out.resize(to.size());
  for (size_t i = 0; i < to.size(); ++i) {
    if (i >= from.size()) {
      out[i] = to[i];
      continue;
    }
    out[i].position = from[i].position + (to[i].position - from[i].position) * weight;
    out[i].orientation = from[i].orientation.slerp(weight, to[i].orientation);
  }
}

render::Vec3f impulse_on(const physics::ContactRecord& contact, int body) {
  const double sign = body == contact.body_a ? 1.0 : -1.0;  // B gets the opposite of A's
  return (sign * (contact.normal * contact.normal_impulse)).cast<float>();
}

render::DrawList scene_draw_list(const Scene& scene, const std::vector<physics::Body>& bodies,
                                 const std::vector<BodyPose>& poses, const std::vector<physics::Joint>& joints,
                                 const std::vector<physics::ContactRecord>& contacts, const ArrowScales& scales,
                                 const render::Camera& camera) {
  const DrawOptions& draw = scene.draw;
  render::DrawList list;
  list.camera = camera;
  list.ground = false;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const physics::Body& body = bodies[i];
    const BodyPose& pose = i < poses.size() ? poses[i] : BodyPose{body.position, body.orientation};
    const render::Colour colour = i < scene.colours.size() ? to_render(scene.colours[i]) : render::Colour{};
    const bool sleeping = draw.sleeping && !body.awake && !body.is_static();
    switch (body.shape.type) {
      case physics::ShapeType::sphere:
        list.spheres.push_back({to_float(pose.position), float(body.shape.radius), pose.orientation.cast<float>(),
                                colour, true, sleeping});
        break;
      case physics::ShapeType::box:
        list.boxes.push_back({to_float(pose.position), body.shape.half_extents.cast<float>(),
                              pose.orientation.cast<float>(), colour, sleeping});
        break;
      case physics::ShapeType::cylinder:
        list.cylinders.push_back({to_float(pose.position), float(body.shape.radius), float(body.shape.half_height),
                                  pose.orientation.cast<float>(), colour, true, sleeping});
        break;
      case physics::ShapeType::capsule: {
        // The cylinder of its segment and a ball at each end, all marked in the capsule's frame:
        // each ball's octants beyond the segment continue the segment's half they close.
        const render::Quatf orientation = pose.orientation.cast<float>();
        const render::Vec3f centre = to_float(pose.position);
        const float radius = float(body.shape.radius), half_height = float(body.shape.half_height);
        list.cylinders.push_back({centre, radius, half_height, orientation, colour, true, sleeping});
        const render::Vec3f end = orientation * render::Vec3f(0.0f, half_height, 0.0f);
        for (const float side : {1.0f, -1.0f})
          list.spheres.push_back({centre + side * end, radius, orientation, colour, true, sleeping});
        break;
      }
      case physics::ShapeType::hull:
        if (body.shape.hull())
          list.meshes.push_back({to_float(pose.position), pose.orientation.cast<float>(), hull_triangles(body.shape.shared_hull()),
                                 colour, sleeping});
        break;
      case physics::ShapeType::mesh:
        if (body.shape.mesh())
          list.meshes.push_back({to_float(pose.position), pose.orientation.cast<float>(), mesh_triangles(body.shape.shared_mesh()), colour, false});
        break;
      case physics::ShapeType::plane:
        // The renderer draws one ground; a horizontal plane becomes it, any other a slab.
        if (body.shape.normal.y() > 0.999) {
          list.ground = true;
          list.ground_height = float(body.shape.offset);
        } else {
          list.boxes.push_back(plane_slab(body.shape, camera, colour));
        }
        break;
    }
    if (draw.velocities && !body.is_static())
      add_arrow(list, to_float(pose.position), to_float(body.velocity) * float(scales.velocity), mark_colour::velocity, velocity_layer);
  }

  add_joints(list, poses, joints);
  if (draw.contact_points)
    for (const physics::ContactRecord& contact : contacts)
      list.points.push_back({to_float(contact.point), mark_colour::contact_point, 4.0f,
                             kDotShare * std::min(contact_body_size(bodies, contact.body_a), contact_body_size(bodies, contact.body_b))});
  const std::vector<physics::ContactRecord> marked = marked_contacts(contacts, draw.marked_pairs);
  double strongest = 0;
  for (const physics::ContactRecord& contact : marked) strongest = std::max(strongest, contact.normal_impulse);
  for (const physics::ContactRecord& contact : marked) {
    const render::Vec3f point = to_float(contact.point);
    // The normal the way the impulse arrow drawn first pushes: A's where A moves, else B's (a block
    // on the ground shows both pointing up, out of the ground).
    const float facing = moves(bodies, contact.body_a) ? 1.0f : -1.0f;
    if (draw.contact_normals)
      add_arrow(list, point, facing * to_float(contact.normal) * float(scales.normal_length), mark_colour::contact_normal, normal_layer);
    const bool resting = contact.normal_impulse < draw.faint_below * strongest;
    const render::Colour normal_colour = resting ? faint(mark_colour::normal_impulse) : mark_colour::normal_impulse;
    const render::Colour friction_colour = resting ? faint(mark_colour::friction_impulse) : mark_colour::friction_impulse;
    for (int body : {contact.body_a, contact.body_b}) {
      if (!moves(bodies, body)) continue;
      const float sign = body == contact.body_a ? 1.0f : -1.0f;
      if (draw.impulses)
        add_arrow(list, point, cut_to(impulse_on(contact, body) * float(scales.impulse), scales.longest_impulse),
                  normal_colour, impulse_layer);
      if (draw.friction)
        add_arrow(list, point, cut_to(sign * to_float(contact.tangent_impulse) * float(scales.impulse), scales.longest_impulse),
                  friction_colour, friction_layer);
    }
  }
  return list;
}

}  // namespace impulse::demos
