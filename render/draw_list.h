// What one frame shows, as plain data. The demos layer fills it from the world and the step's
// records; the renderer only draws it. render/ knows nothing of physics/.
#pragma once
#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <vector>

namespace impulse::render {

using Vec3f = Eigen::Vector3f;
using Quatf = Eigen::Quaternionf;

struct Colour { float r = 0.8f, g = 0.8f, b = 0.8f; };

// spin_marks darkens alternate octants of the sphere so its rotation is visible. A sleeping body
// is drawn pale and hatched, so it reads as asleep without relying on colour.
struct SphereItem {
  Vec3f centre;
  float radius = 0.5f;
  Quatf orientation = Quatf::Identity();
  Colour colour;
  bool spin_marks = true;
  bool sleeping = false;
};
struct BoxItem {
  Vec3f centre;
  Vec3f half_extents{0.5f, 0.5f, 0.5f};
  Quatf orientation = Quatf::Identity();
  Colour colour;
  bool sleeping = false;
};
// A solid circular cylinder: its axis along its local y, its flat faces at y = +-half_height. (A
// capsule is drawn as one with a sphere at each end.) spin_marks darkens alternate octants of its
// own frame, as a sphere's: four sectors about its axis, swapped between its halves and carried
// onto the caps, so the balls of a capsule, in its orientation, continue the pattern.
struct CylinderItem {
  Vec3f centre;
  float radius = 0.5f;
  float half_height = 0.5f;
  Quatf orientation = Quatf::Identity();
  Colour colour;
  bool spin_marks = true;
  bool sleeping = false;
};
// A polyhedron (a convex hull, or any closed mesh), drawn flat: one shade a triangle, the sides of
// its faces outlined as a box's edges. `triangles` holds its corners in its own frame (about
// `centre`, turned by `orientation`), three a triangle, counter-clockwise seen from outside;
// neighbouring triangles in one plane make one face, with no line between them. It is shared, not
// copied: the renderer uploads one GPU mesh per distinct vector, keyed by its address and holding
// it while the mesh is kept (so the address cannot come to name other corners), so every item and
// frame that shares one vector costs one upload.
struct MeshItem {
  Vec3f centre;
  Quatf orientation = Quatf::Identity();
  std::shared_ptr<const std::vector<Vec3f>> triangles;
  Colour colour;
  bool sleeping = false;
};
// An arrow from `origin` along `direction` (its length is the arrow's length in metres).
// Arrows and points are drawn in flat colours, and faintly where a body hides them. Where arrows
// overlap (e.g. a velocity and an impulse along one line), the higher `layer` is drawn on top.
struct ArrowItem { Vec3f origin; Vec3f direction; Colour colour; int layer = 0; };
// A dot of a fixed size on screen (e.g. a contact point), whatever its distance.
// A dot of `radius_pixels` on screen, but no larger than `largest_radius` metres where it is (a
// fraction of the bodies it marks: a small ball's contact stays a dot on it).
struct PointItem { Vec3f position; Colour colour; float radius_pixels = 4.0f; float largest_radius = INFINITY; };
// A straight line of a fixed width on screen (e.g. a rod or rope joint), drawn like an arrow's shaft.
struct LineItem { Vec3f from; Vec3f to; Colour colour; float width_pixels = 3.0f; };

struct Camera {
  Vec3f position{0.0f, 3.0f, 10.0f};
  Vec3f target{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
};

struct DrawList {
  Camera camera;
  Colour background{0.92f, 0.94f, 0.97f};
  // Direction to the one directional light (any length): high, so a shadow falls almost straight
  // below its body and the gap between them shows the height.
  Vec3f towards_light{-0.3f, 1.0f, 0.35f};
  bool ground = true;         // the plane y = ground_height
  float ground_height = 0.0f;
  std::vector<SphereItem> spheres;
  std::vector<BoxItem> boxes;
  std::vector<CylinderItem> cylinders;
  std::vector<MeshItem> meshes;
  std::vector<ArrowItem> arrows;
  std::vector<PointItem> points;
  std::vector<LineItem> lines;
};

}  // namespace impulse::render
