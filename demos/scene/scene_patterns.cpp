// [[pyramid]] and [[lattice]]: many bodies from one table, for stacks and large scenes (the
// benchmark's scenes, ../shared/bench/SCENES.md, are written this way).
#include "demos/scene/scene_sections.h"
#include "physics/pyramid.h"

#include <iterator>
#include <random>
#include <stdexcept>

namespace impulse::demos {

namespace {

using physics::Real;
using physics::Vec3;

physics::BodyDef base_body(TableReader& r, Scene& scene, const std::string& name) {
  physics::BodyDef def;
  def.name = name;
  def.mass = r.number("mass", 1, 0, kLargestMass, true);
  def.material.restitution = r.number("restitution", 0, 0, 1);
  def.material.friction = r.number("friction", 0.6, 0);
  read_material_kind(r, scene, def);
  def.planar_axis = read_planar(r, scene.planar_axis);
  return def;
}

// Unit-spaced rows of boxes, each row one shorter and half a box further in, centred at x = 0.
void read_pyramid(TableReader& r, Scene& scene) {
  const int base = r.integer("base", 10, 1, 200);
  const Real size = r.number("size", 1, 0, 100, true);
  const Vec3 origin = r.vec3("position", Vec3::Zero(), kFarthest, "m", kFarthestWhy);  // the middle of the base row's bottom
  physics::BodyDef def = base_body(r, scene, "");
  r.finish();
  def.shape = physics::Shape::box(Vec3::Constant(size / 2));
  for (const physics::PyramidBox& box : physics::pyramid_boxes(base, size, origin)) {
    def.name = "pyramid row " + std::to_string(box.row + 1) + " box " + std::to_string(box.column + 1);
    def.position = box.centre;
    scene.bodies.push_back(def);
    scene.colours.push_back(kBodyPalette[box.row % kRowColourCount]);
  }
}

// A count.x by count.y by count.z lattice of boxes or spheres with a seeded jitter and orientation:
// layers up the y axis, `position` the centre of the bottom layer (of its bodies' centres), the
// bodies named "NAME 1", "NAME 2", ... layer by layer, along x, then z. The `number`th [[lattice]]
// of the file is named "lattice" (the first) or "lattice NUMBER" unless it says.
void read_lattice(TableReader& r, Scene& scene, int number) {
  const std::string name = r.string("name", number == 1 ? "lattice" : "lattice " + std::to_string(number));
  const std::string shape = r.choice("shape", "box", {"box", "sphere"});
  const Vec3 count = r.vec3("count", Vec3(10, 10, 10));
  if (count.minCoeff() < 1 || count.prod() > 100000) r.fail(r.get("count"), "count", "each count must be >= 1, at most 100000 bodies");
  const Vec3 pitch = r.vec3("pitch", Vec3(2, 2, 2));
  const Vec3 origin = r.vec3("position", Vec3(0, 1.5, 0), kFarthest, "m", kFarthestWhy);  // centre of the bottom layer
  const Real size = r.number("size", 1, 0, 100, true);      // box edge or sphere diameter
  const Real jitter = r.number("jitter", 0, 0, 100);
  const bool tumble = r.boolean("random_orientation", false);
  const bool stagger = r.boolean("stagger", false);          // odd layers shifted by half a pitch
  const int seed = r.integer("seed", 1, 0, 1 << 30);
  physics::BodyDef def = base_body(r, scene, "");
  def.is_static = r.boolean("static", false);
  const bool coloured = r.has("colour");
  const Colour colour = r.colour("colour", kStaticColour);
  r.finish();
  def.shape = shape == "box" ? physics::Shape::box(Vec3::Constant(size / 2)) : physics::Shape::sphere(size / 2);
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> unit(-1, 1);
  const int nx = int(count.x()), ny = int(count.y()), nz = int(count.z());
  // A staggered layer shifts along the horizontal axes that have more than one body: a lattice one
  // body deep (a Galton board's pegs) stays in its plane.
  const Real shift_x = nx > 1 ? 0.5 : 0, shift_z = nz > 1 ? 0.5 : 0;
  int made = 0;
  for (int layer = 0; layer < ny; ++layer)
    for (int i = 0; i < nx; ++i)
      for (int k = 0; k < nz; ++k) {
        const bool shifted = stagger && layer % 2;
        def.name = name + " " + std::to_string(++made);
        def.position = origin +
                       Vec3(pitch.x() * (i - (nx - 1) / 2.0 + (shifted ? shift_x : 0)), pitch.y() * layer,
                            pitch.z() * (k - (nz - 1) / 2.0 + (shifted ? shift_z : 0))) +
                       jitter * Vec3(unit(random), unit(random), unit(random));
        if (tumble) def.orientation = physics::Quat(unit(random), unit(random), unit(random), unit(random)).normalized();
        scene.bodies.push_back(def);
        scene.colours.push_back(coloured || def.is_static ? colour : kBodyPalette[layer % kRowColourCount]);
      }
}

}  // namespace

void read_patterns(TableReader& top, Scene& scene) {
  if (const toml::array* list = top.table_list("pyramid"))
    for (size_t i = 0; i < list->size(); ++i) {
      TableReader r = top.child(*list->get(i)->as_table(), "[[pyramid]] " + std::to_string(i + 1));
      read_pyramid(r, scene);
    }
  if (const toml::array* list = top.table_list("lattice"))
    for (size_t i = 0; i < list->size(); ++i) {
      TableReader r = top.child(*list->get(i)->as_table(), "[[lattice]] " + std::to_string(i + 1));
      read_lattice(r, scene, int(i) + 1);
    }
}

}  // namespace impulse::demos
