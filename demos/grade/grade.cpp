#include "demos/grade/grade.h"

#include "demos/scene/scene_sections.h"
#include "demos/scene/scene_world.h"
#include "demos/grade/grade_case.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impulse::workshop {

namespace {

const std::vector<GradeCaseSpec>& all_cases() {
  static const std::vector<GradeCaseSpec> cases = [] {
    std::vector<GradeCaseSpec> list = collision_cases();
    for (GradeCaseSpec& spec : contact_cases()) list.push_back(std::move(spec));
    return list;
  }();
  return cases;
}

const GradeCaseSpec& find_case(const std::string& name) {
  for (const GradeCaseSpec& spec : all_cases())
    if (spec.name == name) return spec;
  std::string known;
  for (const GradeCaseSpec& spec : all_cases()) known += (known.empty() ? "" : ", ") + spec.name;
  throw std::invalid_argument("no grade case is named '" + name + "' (the cases: " + known + ")");
}

void add_body(demos::Scene& scene, physics::BodyDef def, double restitution, double friction) {
  def.material.restitution = restitution;
  def.material.friction = friction;
  scene.colours.push_back(def.is_static ? demos::kStaticColour
                                        : demos::kBodyPalette[(scene.colours.size()) % std::size(demos::kBodyPalette)]);
  scene.bodies.push_back(std::move(def));
}

// What a response that failed (crashed, looped, made a NaN) is told, from the report's words.
std::string failure_hint(const std::string& report) {
  if (report.find("not a number") != std::string::npos)
    return "a NaN: a division by zero, or a zero vector normalised (the tangent of a head-on hit, line 109; impulse's "
           "Normalize keeps zero zero, a Normalize of your own may not). DBG_CHECKVECTOR says where";
  if (report.find("did not return") != std::string::npos)
    return "it never returned: a loop whose condition never changes?";
  if (report.find("SIGSEGV") != std::string::npos) return "it touched memory it may not: a bad pointer, or an index past an array's end";
  return "it stopped the process that runs it: see the report";
}

}  // namespace

const physics::Body& Run::body(size_t step, const std::string& name) const { return states.at(step).at(size_t(index_of(name))); }

int Run::index_of(const std::string& name) const {
  for (size_t i = 0; i < states.front().size(); ++i)
    if (states.front()[i].name == name) return int(i);
  throw std::logic_error("the grade case has no body '" + name + "'");
}

int Run::first_touch(const std::string& a, const std::string& b) const {
  const int ia = index_of(a), ib = index_of(b);
  for (size_t step = 0; step < contacts.size(); ++step)
    for (const physics::ContactRecord& c : contacts[step])
      if (c.penetration >= 0 && ((c.body_a == ia && c.body_b == ib) || (c.body_a == ib && c.body_b == ia))) return int(step);
  return -1;
}

int Run::first_apart(const std::string& a, const std::string& b, int from) const {
  const int ia = index_of(a), ib = index_of(b);
  for (size_t step = size_t(from) + 1; step < contacts.size(); ++step) {
    bool touching = false;
    for (const physics::ContactRecord& c : contacts[step])
      touching = touching || (c.penetration >= 0 && ((c.body_a == ia && c.body_b == ib) || (c.body_a == ib && c.body_b == ia)));
    if (!touching) return int(step);
  }
  return -1;
}

demos::Scene case_base(const std::string& title, double duration, bool gravity) {
  demos::Scene scene;
  scene.path = "impulse grade";
  scene.title = title;
  scene.duration = duration;
  scene.world.method = physics::ResponseMethod::workshop;
  scene.world.reference_listing = true;
  scene.world.sleep.enabled = false;
  if (!gravity) scene.world.gravity = physics::Vec3::Zero();
  return scene;
}

GradeCaseSpec grade_case_spec(std::string name, std::string title, std::string law, const CaseStage& stage,
                              std::function<void(demos::Scene&)> cast) {
  GradeCaseSpec spec;
  spec.name = std::move(name);
  spec.title = std::move(title);
  spec.law = std::move(law);
  spec.scene = [title = spec.title, stage, cast = std::move(cast)] {
    demos::Scene scene = case_base(title, stage.duration, stage.gravity);
    cast(scene);
    scene.camera.position = stage.eye;
    scene.camera.target = stage.target;
    return scene;
  };
  return spec;
}

void add_ground(demos::Scene& scene, double restitution, double friction) {
  physics::BodyDef ground;
  ground.name = "ground";
  ground.shape = physics::Shape::plane(physics::Vec3::UnitY(), 0);
  ground.is_static = true;
  add_body(scene, ground, restitution, friction);
}

void add_sphere(demos::Scene& scene, const std::string& name, double radius, double mass, const physics::Vec3& position,
                const physics::Vec3& velocity, double restitution, double friction) {
  physics::BodyDef def;
  def.name = name;
  def.shape = physics::Shape::sphere(radius);
  def.mass = mass;
  def.position = position;
  def.velocity = velocity;
  add_body(scene, def, restitution, friction);
}

void add_box(demos::Scene& scene, const std::string& name, const physics::Vec3& half_extents, double mass, const physics::Vec3& position,
             const physics::Vec3& velocity, double restitution, double friction) {
  physics::BodyDef def;
  def.name = name;
  def.shape = physics::Shape::box(half_extents);
  def.mass = mass;
  def.position = position;
  def.velocity = velocity;
  add_body(scene, def, restitution, friction);
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const GradeCaseSpec& spec : all_cases()) names.push_back(spec.name);
  return names;
}

demos::Scene case_scene(const std::string& name) { return find_case(name).scene(); }

CaseResult grade_case(const std::string& name, const physics::OutsideResponseMaker& response, const std::string& source) {
  const GradeCaseSpec& spec = find_case(name);
  CaseResult result;
  result.name = spec.name;
  result.title = spec.title;
  result.law = spec.law;
  demos::Scene scene = spec.scene();
  if (response) {
    scene.world.reference_listing = false;
    scene.world.response = response;
  }
  Run run;
  run.dt = scene.world.time_step;
  run.source = source;
  try {
    physics::World world = demos::build_world(scene);
    run.states.push_back(world.bodies());
    const long steps = std::lround(scene.duration / run.dt);
    for (long step = 0; step < steps; ++step) {
      world.step();
      run.states.push_back(world.bodies());
      run.contacts.push_back(world.record().contacts);
    }
  } catch (const physics::ResponseFailure& failure) {
    result.failure = failure.what();
    result.measured = "the response failed";
    result.hint = failure_hint(result.failure);
    return result;
  } catch (const std::runtime_error& error) {  // what it did broke the world (a body's state no longer finite)
    result.failure = error.what();
    result.measured = "the world failed";
    result.hint = "the velocities it left grew without bound: an impulse with the wrong sign pushes bodies together harder "
                  "every step (a contact must push them apart: + J n on c0, - J n on c1)";
    return result;
  }
  const Verdict verdict = spec.judge(run);
  result.expected = verdict.expected;
  result.measured = verdict.measured;
  result.passed = verdict.passed;
  result.hint = verdict.passed ? "" : verdict.hint;
  return result;
}

std::vector<CaseResult> grade(const physics::OutsideResponseMaker& response, const std::string& only, const std::string& source) {
  if (!only.empty()) return {grade_case(only, response, source)};
  std::vector<CaseResult> results;
  for (const GradeCaseSpec& spec : all_cases()) results.push_back(grade_case(spec.name, response, source));
  return results;
}

std::string response_source(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace impulse::workshop
