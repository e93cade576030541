// [world], [[body]] and [[joint]]: what the physics simulates.
#include "demos/scene/rotation_degrees.h"
#include "demos/scene/scene_overrides.h"
#include "demos/scene/scene_response.h"
#include "demos/scene/scene_sections.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <stdexcept>

namespace impulse::demos {

namespace {

using physics::Real;
using physics::Vec3;

// Appends a body after the engine's own checks, reported at the table's line.
void add_body(TableReader& r, const physics::BodyDef& def, Colour colour, Scene& scene) {
  try {
    physics::make_body(def);
  } catch (const std::invalid_argument& error) {
    r.fail(nullptr, "", error.what());
  }
  scene.bodies.push_back(def);
  scene.colours.push_back(colour);
}

void read_body(const TableReader& top, const toml::table& table, int index, Scene& scene) {
  physics::BodyDef def;
  def.name = "body " + std::to_string(index + 1);
  if (auto name = table.get_as<std::string>("name")) def.name = name->get();
  TableReader r = top.child(table, "[[body]] '" + def.name + "'");
  r.get("name");
  const std::string shape =
      r.choice("shape", "", {"sphere", "box", "capsule", "cylinder", "hull", "wedge", "tetrahedron", "prism", "mesh", "plane"});
  // A hull's points in the body's frame, about `position` (its centre of mass and principal axes
  // are found once the inertia's spread is known).
  std::vector<Vec3> points;
  std::string points_field;
  if (shape == "sphere") {
    def.shape = physics::Shape::sphere(r.number("radius", 0.5, 0, kLargestSize, true));
  } else if (shape == "capsule" || shape == "cylinder") {
    // Along the body's y: a cylinder's height, a capsule's between its two balls' centres (its
    // whole length is height + 2 radius).
    const Real radius = r.number("radius", 0.5, 0, kLargestSize, true);
    const Real height = r.number("height", 1, 0, kLargestSize, true);
    def.shape = shape == "capsule" ? physics::Shape::capsule(radius, height / 2) : physics::Shape::cylinder(radius, height / 2);
  } else if (shape == "hull") {
    points_field = "points";
    points = r.points("points", kLargestSize, 1000);
    if (points.empty()) r.fail(r.get("points"), "points", "a hull needs its points: points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]] (metres, in the body's frame)");
  } else if (shape == "wedge") {  // the right triangle in x-y, its right angle at (-x/2, -y/2), drawn along z
    points_field = "size";
    const Vec3 size = r.vec3("size", Vec3(1, 0.5, 0.5), kLargestSize, "m", "a lecture's bodies are smaller");
    if (!(size.minCoeff() > 0)) r.fail(r.get("size"), "size", "every edge must be > 0 (metres: [x, y, z])");
    points = physics::wedge_points(size);
  } else if (shape == "tetrahedron") {  // regular, one face down
    points_field = "size";
    points = physics::tetrahedron_points(r.number("size", 0.5, 0, kLargestSize, true));
  } else if (shape == "prism") {  // `sides` sides about the y axis
    points_field = "sides";
    const int sides = r.integer("sides", 6, 3, 16);
    const Real radius = r.number("radius", 0.5, 0, kLargestSize, true);
    points = physics::prism_points(sides, radius, r.number("height", 1, 0, kLargestSize, true));
  } else if (shape == "box") {
    const Vec3 size = r.vec3("size", Vec3(1, 1, 1), kLargestSize, "m", "a lecture's bodies are smaller");
    if (!(size.minCoeff() > 0)) r.fail(r.get("size"), "size", "every edge must be > 0 (metres: [x, y, z])");
    def.shape = physics::Shape::box(size / 2);
  } else if (shape == "mesh") {  // a static surface: an OBJ file's triangles, from the scene's folder
    const std::string file = r.string("file", "");
    if (file.empty()) r.fail(r.get("file"), "file", "a mesh needs its file: file = \"bowl.obj\" (a Wavefront OBJ, beside the scene file)");
    const double scale = r.number("scale", 1, 0, kLargestSize, true);
    const std::filesystem::path path = std::filesystem::path(file).is_relative() ? std::filesystem::path(scene.path).parent_path() / file
                                                                                 : std::filesystem::path(file);
    try {
      def.shape = physics::Shape::surface(read_mesh_file(path.string(), scale));
    } catch (const std::runtime_error& error) {
      r.fail(r.get("file"), "file", error.what());
    }
    def.is_static = true;
  } else if (shape == "plane") {
    // The points x with normal·x = offset, for a normal of any length: the plane lies offset/|normal|
    // from the origin along it.
    const Vec3 normal = r.vec3("normal", Vec3::UnitY());
    if (!(normal.norm() >= 1e-6))
      r.fail(r.get("normal"), "normal", "must not be the zero vector: it points out of the solid side, like [0, 1, 0]");
    const Real offset = r.number("offset", 0);
    def.shape = physics::Shape::plane(normal / normal.norm(), offset / normal.norm());
    def.is_static = true;
  }
  def.is_static = r.boolean("static", def.is_static);
  if ((shape == "plane" || shape == "mesh") && !def.is_static) r.fail(r.get("static"), "static", "a " + shape + " is always static");
  def.mass = r.number("mass", 0, 0, kLargestMass, true);  // 0: from density
  def.density = r.number("density", def.density, 0, kLargestMass, true);
  // "solid" (the mass through the volume), "hollow" (a thin shell), or the three principal moments.
  const toml::node* inertia = r.get("inertia");
  if (inertia && !inertia->is_array() && !inertia->is_string())
    r.fail(inertia, "inertia", "must be \"solid\", \"hollow\" (a thin shell) or the three principal moments [Ix, Iy, Iz] in kg m\u00b2");
  if (inertia && inertia->is_array()) {
    def.principal_inertia = r.vec3("inertia", Vec3::Zero(), kLargestMass, "kg m\u00b2", "a lecture's bodies are lighter");
    const Vec3 i = def.principal_inertia;
    if (!(i.minCoeff() > 0) || 2 * i.maxCoeff() > i.sum() * (1 + 1e-12))
      r.fail(inertia, "inertia",
             "the three principal moments (kg m\u00b2, about the body's x, y, z) must be > 0, none larger than the other two "
             "together, as a rigid body's are (a solid ball of 1 kg and 0.1 m: [0.004, 0.004, 0.004]); or say \"solid\" or \"hollow\"");
  } else if (r.choice("inertia", "solid", {"solid", "hollow"}) == "hollow")
    def.spread = physics::MassSpread::hollow;
  def.material.restitution = r.number("restitution", def.material.restitution, 0, 1);
  def.material.friction = r.number("friction", def.material.friction, 0);
  read_material_kind(r, scene, def);
  def.position = r.vec3("position", def.position, kFarthest, "m", kFarthestWhy);
  def.orientation = rotation_from_degrees(r.vec3("rotation", Vec3::Zero()));
  if (!points.empty()) {
    physics::PlacedHull placed;
    try {
      placed = physics::place_hull(points, def.spread == physics::MassSpread::hollow);
    } catch (const std::invalid_argument& error) {
      r.fail(r.get(points_field), points_field, error.what());
    }
    def.shape = physics::Shape::convex(placed.hull);
    def.position += physics::rotate(def.orientation, placed.centre);
    def.orientation = (def.orientation * placed.frame).normalized();
  }
  def.velocity = r.vec3("velocity", def.velocity, kFastest, "m/s", kFastestWhy);
  def.angular_velocity = r.vec3("angular_velocity", def.angular_velocity, kFastestSpin, "rad/s", kFastestSpinWhy);
  def.planar_axis = read_planar(r, scene.planar_axis);
  const Colour colour = r.colour("colour", def.is_static ? kStaticColour : kBodyPalette[index % std::size(kBodyPalette)]);
  r.finish();
  add_body(r, def, colour, scene);
}

int body_index(TableReader& r, const Scene& scene, std::string_view key) {
  const std::string name = r.string(key, "world");
  if (name == "world") return physics::kWorld;
  if (const int index = find_body(scene, name); index >= 0) return index;
  std::vector<std::string> names;
  for (const physics::BodyDef& body : scene.bodies) names.push_back(body.name);
  const std::string hint = did_you_mean(name, names);
  r.fail(r.get(key), key,
         "no body is named '" + name + "'" + (hint.empty() ? "" : "; " + hint) +
             " (give a [[body]] that name, or say \"world\")");
}

}  // namespace

void read_world(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("world");
  if (!t) return;
  TableReader r = top.child(*t, "[world]");
  auto& w = scene.world;
  w.gravity = r.vec3("gravity", w.gravity);
  scene.planar_axis = read_planar(r, physics::kNotPlanar);
  w.time_step = 1 / r.number("step_rate", 1 / w.time_step, 1, 100000);
  w.substeps = r.integer("substeps", w.substeps, 1, 64);
  w.min_substeps = r.integer("min_substeps", w.min_substeps, 1, 64);
  w.stack_sink = r.number("stack_sink", w.stack_sink, 0, 1);
  w.moving_overlap = r.number("moving_overlap", w.moving_overlap, 0, 1);
  w.method = *physics::method_from_name(r.choice("method", "impulse", physics::method_names()));
  if (r.choice("eq8_sign", "corrected", {"corrected", "printed"}) == "printed") {
    if (w.method != physics::ResponseMethod::workshop)
      r.fail(r.get("eq8_sign"), "eq8_sign", "only listing 1 runs eq. 8 as printed: set method = \"workshop\" too");
    w.printed_eq8_sign = true;
  }
  read_response(r, scene);  // a student's AddCollisionImpulse (scene_response.h)
  w.contact.friction = r.boolean("friction", w.contact.friction);
  w.contact.restitution_threshold = r.number("restitution_threshold", w.contact.restitution_threshold, 0);
  w.contact.rolling_resistance = r.number("rolling_resistance", w.contact.rolling_resistance, 0, 1);
  w.contact.contact_hertz = r.number("contact_hertz", w.contact.contact_hertz, 0, 10000, true);
  w.sleep.enabled = r.boolean("sleeping", w.sleep.enabled);
  w.threads = r.integer("threads", w.threads, 0, 64);  // 0: one per core; the results do not depend on it
  w.penalty.hertz = r.number("penalty_hertz", w.penalty.hertz, 0, 10000, true);
  w.penalty.damping_ratio = r.number("penalty_damping_ratio", w.penalty.damping_ratio, 0);
  r.finish();
}

int read_planar(TableReader& r, int fallback) {
  // Each plane by the two axes it holds; the lock is about the third.
  static constexpr std::string_view kPlanes[] = {"yz", "xz", "xy", "none"};
  const std::string plane = r.choice("planar", std::string(fallback == physics::kNotPlanar ? kPlanes[3] : kPlanes[fallback]), kPlanes);
  for (int axis = 0; axis < 3; ++axis)
    if (plane == kPlanes[axis]) return axis;
  return physics::kNotPlanar;
}

void read_material_kind(TableReader& r, Scene& scene, physics::BodyDef& def) {
  if (!r.has("material")) return;
  const std::string name = r.string("material", "");
  if (name.empty()) r.fail(r.get("material"), "material", "a material needs a name, like \"ball\" or \"cloth\"");
  auto known = std::find(scene.material_names.begin(), scene.material_names.end(), name);
  def.material.kind = int(known - scene.material_names.begin());
  if (known == scene.material_names.end()) scene.material_names.push_back(name);
}

// [[material_pair]]: friction and restitution for contacts between bodies of two materials (or of
// one, named twice), in place of the mixing rules (physics/materials.h).
void read_material_pairs(TableReader& top, Scene& scene) {
  const toml::array* pairs = top.table_list("material_pair");
  if (!pairs) return;
  for (size_t i = 0; i < pairs->size(); ++i) {
    TableReader r = top.child(*pairs->get(i)->as_table(), "[[material_pair]] " + std::to_string(i + 1));
    const toml::node* between = r.get("between");
    const toml::array* names = between ? between->as_array() : nullptr;
    const char* form = "two materials, like between = [\"ball\", \"cloth\"] (a body says material = \"ball\")";
    if (!names || names->size() != 2 || !names->get(0)->is_string() || !names->get(1)->is_string()) r.fail(between, "between", form);
    physics::PairMaterial pair;
    int* kinds[2] = {&pair.kind_a, &pair.kind_b};
    for (int k = 0; k < 2; ++k) {
      const std::string name = names->get(k)->as_string()->get();
      auto known = std::find(scene.material_names.begin(), scene.material_names.end(), name);
      if (known == scene.material_names.end()) {
        const std::string hint = did_you_mean(name, scene.material_names);
        r.fail(between, "between",
               "no body has material = \"" + name + "\"" + (hint.empty() ? "" : "; " + hint) +
                   (scene.material_names.empty() ? " (no body names a material yet: add material = \"" + name + "\" to its [[body]])" : ""));
      }
      *kinds[k] = int(known - scene.material_names.begin());
    }
    if (r.has("friction")) pair.friction = r.number("friction", 0, 0);
    if (r.has("restitution")) pair.restitution = r.number("restitution", 0, 0, 1);
    if (!pair.friction && !pair.restitution) r.fail(between, "between", "give the pair a friction, a restitution or both");
    r.finish();
    scene.world.pair_materials.push_back(pair);
  }
}

void read_bodies(TableReader& top, Scene& scene) {
  const toml::array* bodies = top.table_list("body");
  if (!bodies) return;
  for (size_t i = 0; i < bodies->size(); ++i) read_body(top, *bodies->get(i)->as_table(), int(i), scene);
}

void read_joints(TableReader& top, Scene& scene) {
  const toml::array* joints = top.table_list("joint");
  if (!joints) return;
  for (size_t i = 0; i < joints->size(); ++i) {
    const toml::table& table = *joints->get(i)->as_table();
    physics::JointDef def;
    def.name = "joint " + std::to_string(i + 1);
    if (auto name = table.get_as<std::string>("name")) def.name = name->get();
    TableReader r = top.child(table, "[[joint]] '" + def.name + "'");
    r.get("name");
    const std::string type = r.choice("type", "", {"ball", "hinge", "rod", "rope"});
    def.body_a = body_index(r, scene, "a");
    def.body_b = body_index(r, scene, "b");
    if (def.body_a == def.body_b) r.fail(r.get("b"), "b", "a joint joins two different bodies");
    if (type == "ball" || type == "hinge") {
      // The shared point: by default the centre of `a` (of `b` when `a` is the world), so that a
      // body pinned to the world turns about its own centre.
      def.type = type == "ball" ? physics::JointType::ball : physics::JointType::hinge;
      const int pinned = def.body_a == physics::kWorld ? def.body_b : def.body_a;
      def.anchor = r.vec3("anchor", scene.bodies[pinned].position);
      if (type == "hinge") def.axis = r.vec3("axis", Vec3::UnitZ());
    } else {
      // Each end at its body's centre by default; the world has none, so its end is given.
      def.type = physics::JointType::distance;
      def.rope = type == "rope";
      auto end = [&](int body, const char* key) {
        if (body != physics::kWorld) return r.vec3(key, scene.bodies[body].position);
        if (!r.has(key))
          r.fail(nullptr, key, std::string("missing: the fixed point the ") + type + " hangs from (world coordinates, m), like [0, 2, 0]");
        return r.vec3(key, Vec3::Zero());
      };
      def.anchor_a = end(def.body_a, "anchor_a");
      def.anchor_b = end(def.body_b, "anchor_b");
      def.length = r.number("length", 0, 0);  // 0: the distance between the anchors
    }
    r.finish();
    scene.joints.push_back(def);
  }
}

}  // namespace impulse::demos
