#include "demos/scene_file.h"

#include <toml++/toml.h>

#include <cmath>
#include <set>
#include <sstream>

namespace impulse::demos {

namespace {

using physics::Real;
using physics::Vec3;

// Reads one TOML table, checking each field's type and range, and reports any key it was not
// asked for (a typo would otherwise be silently ignored).
class TableReader {
 public:
  TableReader(const toml::table& table, std::string file, std::string where)
      : table_(table), file_(std::move(file)), where_(std::move(where)) {}

  [[noreturn]] void fail(const toml::node* node, std::string_view key, const std::string& reason) const {
    const auto& source = node ? node->source() : table_.source();
    std::ostringstream message;
    message << file_ << ':' << source.begin.line << ": " << where_ << (key.empty() ? "" : " field '") << key
            << (key.empty() ? "" : "'") << ": " << reason;
    throw SceneError(message.str());
  }

  const toml::node* get(std::string_view key) {
    used_.insert(std::string(key));
    return table_.get(key);
  }

  double number(std::string_view key, double fallback, double min = -INFINITY, double max = INFINITY,
                bool exclusive_min = false) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    double value;
    if (auto v = node->value_exact<double>()) value = *v;
    else if (auto i = node->value_exact<int64_t>()) value = double(*i);
    else fail(node, key, "must be a number");
    if (!std::isfinite(value)) fail(node, key, "must be finite");
    const bool too_small = exclusive_min ? value <= min : value < min;
    if (too_small || value > max) {
      std::ostringstream range;
      range << "must be " << (exclusive_min ? "> " : ">= ") << min;
      if (std::isfinite(max)) range << " and <= " << max;
      range << ", got " << value;
      fail(node, key, range.str());
    }
    return value;
  }

  int integer(std::string_view key, int fallback, int min, int max) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    auto v = node->value_exact<int64_t>();
    if (!v) fail(node, key, "must be a whole number");
    if (*v < min || *v > max)
      fail(node, key, "must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " + std::to_string(*v));
    return int(*v);
  }

  bool boolean(std::string_view key, bool fallback) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    auto v = node->value_exact<bool>();
    if (!v) fail(node, key, "must be true or false");
    return *v;
  }

  std::string string(std::string_view key, std::string fallback) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    auto v = node->value_exact<std::string>();
    if (!v) fail(node, key, "must be a string in quotes");
    return *v;
  }

  Vec3 vec3(std::string_view key, const Vec3& fallback) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    const toml::array* array = node->as_array();
    if (!array || array->size() != 3) fail(node, key, "must be an array of three numbers, like [0, 1, 0]");
    Vec3 v;
    for (int i = 0; i < 3; ++i) {
      const toml::node& item = *array->get(i);
      if (auto d = item.value_exact<double>()) v[i] = *d;
      else if (auto n = item.value_exact<int64_t>()) v[i] = Real(*n);
      else fail(node, key, "must be an array of three numbers, like [0, 1, 0]");
      if (!std::isfinite(v[i])) fail(node, key, "must be finite");
    }
    return v;
  }

  render::Colour colour(std::string_view key, render::Colour fallback) {
    const toml::node* node = get(key);
    if (!node) return fallback;
    auto text = node->value_exact<std::string>();
    unsigned rgb = 0;
    if (!text || text->size() != 7 || (*text)[0] != '#' || std::sscanf(text->c_str() + 1, "%6x", &rgb) != 1)
      fail(node, key, "must be a colour like \"#e69f00\"");
    return {float((rgb >> 16) & 255) / 255, float((rgb >> 8) & 255) / 255, float(rgb & 255) / 255};
  }

  // Call last: refuses keys the reader was never asked about.
  void finish() const {
    for (const auto& [key, node] : table_) {
      if (used_.count(std::string(key.str()))) continue;
      std::string known;
      for (const auto& k : used_) known += (known.empty() ? "" : ", ") + k;
      fail(&node, key.str(), "unknown field (known here: " + known + ")");
    }
  }

 private:
  const toml::table& table_;
  std::string file_;
  std::string where_;
  std::set<std::string> used_;
};

const toml::table* sub_table(TableReader& parent, const toml::table& root, std::string_view key) {
  const toml::node* node = parent.get(key);
  if (!node) return nullptr;
  if (!node->is_table()) parent.fail(node, key, "must be a table, like [" + std::string(key) + "]");
  return root.get_as<toml::table>(key);
}

// Colour-blind-safe palette (Okabe and Ito) for bodies without a colour of their own.
const render::Colour kPalette[] = {{0.90f, 0.62f, 0.00f}, {0.34f, 0.71f, 0.91f}, {0.00f, 0.62f, 0.45f},
                                   {0.80f, 0.47f, 0.65f}, {0.00f, 0.45f, 0.70f}, {0.94f, 0.89f, 0.26f}};

void read_body(const toml::table& table, const std::string& file, int index, Scene& scene) {
  physics::BodyDef def;
  def.name = "body " + std::to_string(index + 1);
  if (auto name = table.get_as<std::string>("name")) def.name = name->get();
  TableReader r(table, file, "[[body]] '" + def.name + "'");
  r.get("name");
  const std::string shape = r.string("shape", "");
  if (shape == "sphere") {
    def.shape = physics::Shape::sphere(r.number("radius", 0.5, 0, INFINITY, true));
  } else if (shape == "plane") {
    const Vec3 normal = r.vec3("normal", Vec3::UnitY());
    if (normal.norm() < 1e-9) r.fail(r.get("normal"), "normal", "must not be the zero vector");
    def.shape = physics::Shape::plane(normal.normalized(), r.number("offset", 0));
    def.is_static = true;
  } else {
    r.fail(shape.empty() ? nullptr : r.get("shape"), "shape",
           shape.empty() ? "missing: every body needs shape = \"sphere\" or \"plane\""
                         : "unknown shape '" + shape + "' (known: sphere, plane)");
  }
  def.is_static = r.boolean("static", def.is_static);
  def.mass = r.number("mass", 0, 0, INFINITY, true);  // 0: from density
  def.density = r.number("density", def.density, 0, INFINITY, true);
  def.material.restitution = r.number("restitution", def.material.restitution, 0, 1);
  def.material.friction = r.number("friction", def.material.friction, 0);
  def.position = r.vec3("position", def.position);
  def.velocity = r.vec3("velocity", def.velocity);
  def.angular_velocity = r.vec3("angular_velocity", def.angular_velocity);
  render::Colour colour = r.colour("colour", kPalette[index % std::size(kPalette)]);
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

Scene load_scene(const std::string& path) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& error) {
    std::ostringstream message;
    message << path << ':' << error.source().begin.line << ": " << error.description();
    if (error.description().find("No such file") != std::string_view::npos || error.source().begin.line == 0)
      message.str(path + ": cannot read the scene file (" + std::string(error.description()) + ")");
    throw SceneError(message.str());
  }

  Scene scene;
  scene.path = path;
  TableReader top(root, path, "scene");

  if (const toml::table* t = sub_table(top, root, "scene")) {
    TableReader r(*t, path, "[scene]");
    scene.title = r.string("title", "");
    scene.duration = r.number("duration", scene.duration, 0, 3600, true);
    r.finish();
  }
  if (const toml::table* t = sub_table(top, root, "world")) {
    TableReader r(*t, path, "[world]");
    auto& w = scene.world;
    w.gravity = r.vec3("gravity", w.gravity);
    w.time_step = 1 / r.number("step_rate", 1 / w.time_step, 1, 100000);
    w.substeps = r.integer("substeps", w.substeps, 1, 64);
    w.contact.friction = r.boolean("friction", w.contact.friction);
    w.contact.restitution_threshold = r.number("restitution_threshold", w.contact.restitution_threshold, 0);
    r.finish();
  }
  if (const toml::table* t = sub_table(top, root, "camera")) {
    TableReader r(*t, path, "[camera]");
    auto& c = scene.camera;
    c.position = r.vec3("position", c.position.cast<Real>()).cast<float>();
    c.target = r.vec3("target", c.target.cast<Real>()).cast<float>();
    c.fov_y_degrees = float(r.number("fov", c.fov_y_degrees, 1, 170));
    r.finish();
  }
  if (const toml::table* t = sub_table(top, root, "video")) {
    TableReader r(*t, path, "[video]");
    auto& v = scene.video;
    v.width = r.integer("width", v.width, 16, 7680);
    v.height = r.integer("height", v.height, 16, 4320);
    if (v.width % 2 || v.height % 2) r.fail(r.get("width"), "width", "width and height must be even (yuv420p)");
    v.fps = r.integer("fps", v.fps, 1, 240);
    v.crf = r.integer("crf", v.crf, 0, 51);
    r.finish();
  }
  if (const toml::table* t = sub_table(top, root, "draw")) {
    TableReader r(*t, path, "[draw]");
    scene.draw.contact_normals = r.boolean("contact_normals", scene.draw.contact_normals);
    scene.draw.normal_length = float(r.number("normal_length", scene.draw.normal_length, 0, 100, true));
    r.finish();
  }
  if (const toml::node* node = top.get("body")) {
    const toml::array* bodies = node->as_array();
    if (!bodies || !bodies->is_array_of_tables()) top.fail(node, "body", "must be a list of [[body]] tables");
    for (size_t i = 0; i < bodies->size(); ++i) read_body(*bodies->get(i)->as_table(), path, int(i), scene);
  }
  top.finish();
  if (scene.bodies.empty()) throw SceneError(path + ":1: scene: no bodies; add at least one [[body]] table");
  return scene;
}

}  // namespace impulse::demos
