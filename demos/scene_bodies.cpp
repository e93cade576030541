// [world] and [[body]]: what the physics simulates.
#include "demos/scene_sections.h"

#include <iterator>
#include <stdexcept>

namespace impulse::demos {

namespace {

using physics::Vec3;

// Colour-blind-safe palette (Okabe and Ito) for bodies without a colour of their own.
const render::Colour kPalette[] = {{0.90f, 0.62f, 0.00f}, {0.34f, 0.71f, 0.91f}, {0.00f, 0.62f, 0.45f},
                                   {0.80f, 0.47f, 0.65f}, {0.00f, 0.45f, 0.70f}, {0.94f, 0.89f, 0.26f}};

void read_body(const toml::table& table, const std::string& path, int index, Scene& scene) {
  physics::BodyDef def;
  def.name = "body " + std::to_string(index + 1);
  if (auto name = table.get_as<std::string>("name")) def.name = name->get();
  TableReader r(table, path, "[[body]] '" + def.name + "'");
  r.get("name");
  const std::string shape = r.choice("shape", "", {"sphere", "plane"});
  if (shape == "sphere") {
    def.shape = physics::Shape::sphere(r.number("radius", 0.5, 0, INFINITY, true));
  } else if (shape == "plane") {
    const Vec3 normal = r.vec3("normal", Vec3::UnitY());
    if (normal.norm() < 1e-9) r.fail(r.get("normal"), "normal", "must not be the zero vector");
    def.shape = physics::Shape::plane(normal.normalized(), r.number("offset", 0));
    def.is_static = true;
  }
  def.is_static = r.boolean("static", def.is_static);
  def.mass = r.number("mass", 0, 0, INFINITY, true);  // 0: from density
  def.density = r.number("density", def.density, 0, INFINITY, true);
  def.material.restitution = r.number("restitution", def.material.restitution, 0, 1);
  def.material.friction = r.number("friction", def.material.friction, 0);
  def.position = r.vec3("position", def.position);
  def.velocity = r.vec3("velocity", def.velocity);
  def.angular_velocity = r.vec3("angular_velocity", def.angular_velocity);
  const render::Colour colour = r.colour("colour", kPalette[index % std::size(kPalette)]);
  r.finish();
  try {
    physics::make_body(def);  // the engine's own checks, reported at this body's line
  } catch (const std::invalid_argument& error) {
    r.fail(nullptr, "", error.what());
  }
  scene.bodies.push_back(def);
  scene.colours.push_back(colour);
}

}  // namespace

void read_world(TableReader& top, Scene& scene) {
  const toml::table* t = top.table("world");
  if (!t) return;
  TableReader r(*t, scene.path, "[world]");
  auto& w = scene.world;
  w.gravity = r.vec3("gravity", w.gravity);
  w.time_step = 1 / r.number("step_rate", 1 / w.time_step, 1, 100000);
  w.substeps = r.integer("substeps", w.substeps, 1, 64);
  w.contact.friction = r.boolean("friction", w.contact.friction);
  w.contact.restitution_threshold = r.number("restitution_threshold", w.contact.restitution_threshold, 0);
  r.finish();
}

void read_bodies(TableReader& top, Scene& scene) {
  const toml::node* node = top.get("body");
  if (!node) return;
  const toml::array* bodies = node->as_array();
  if (!bodies || !bodies->is_array_of_tables()) top.fail(node, "body", "must be a list of [[body]] tables");
  for (size_t i = 0; i < bodies->size(); ++i) read_body(*bodies->get(i)->as_table(), scene.path, int(i), scene);
}

}  // namespace impulse::demos
