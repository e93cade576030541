// What the grade's cases share (grade.h): a case is a scene and a judge; the judge reads the run.
#pragma once
#include "demos/scene/scene.h"
#include "physics/body.h"
#include "physics/step_record.h"

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace impulse::workshop {

// A case's world, step by step: the bodies at the start (states[0]) and after each step, and each
// step's contacts (contacts[k] belongs to states[k + 1]).
struct Run {
  double dt = 0;
  std::vector<std::vector<physics::Body>> states;
  std::vector<std::vector<physics::ContactRecord>> contacts;
  std::string source;  // the student's file, whose lines a hint may name (empty: the engine's reference)

  const physics::Body& body(size_t step, const std::string& name) const;
  // The first step whose contacts include one between the two bodies, or -1; and the first after
  // `from` without one.
  int first_touch(const std::string& a, const std::string& b) const;
  int first_apart(const std::string& a, const std::string& b, int from) const;
  int index_of(const std::string& name) const;
};

struct Verdict {
  bool passed = false;
  std::string expected, measured, hint;
};

struct GradeCaseSpec {
  std::string name, title, law;
  std::function<demos::Scene()> scene;
  std::function<Verdict(const Run&)> judge;
};

// Where a case happens: case_base's world for `duration` s, with gravity or without, seen from
// `eye` toward `target`.
struct CaseStage {
  double duration = 1;
  bool gravity = false;
  demos::Vec3f eye, target;
};

// A case: its name, title and law, and its scene (the stage, with the bodies `cast` adds); its
// judge is the caller's to set.
GradeCaseSpec grade_case_spec(std::string name, std::string title, std::string law, const CaseStage& stage,
                              std::function<void(demos::Scene&)> cast);

// The cases of grade_collisions.cpp and grade_contacts.cpp, in the order they run.
std::vector<GradeCaseSpec> collision_cases();
std::vector<GradeCaseSpec> contact_cases();

// A scene for a case: the workshop method with the reference page (grade.cpp puts the student's
// response in its place), sleeping off (a jiggle must show), `gravity` or none.
demos::Scene case_base(const std::string& title, double duration, bool gravity);
void add_ground(demos::Scene& scene, double restitution, double friction);
void add_sphere(demos::Scene& scene, const std::string& name, double radius, double mass, const physics::Vec3& position,
                const physics::Vec3& velocity, double restitution, double friction);
void add_box(demos::Scene& scene, const std::string& name, const physics::Vec3& half_extents, double mass,
             const physics::Vec3& position, const physics::Vec3& velocity, double restitution, double friction);

// printf into a string.
template <class... Args>
std::string format(const char* pattern, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, args...);
  return text;
}

}  // namespace impulse::workshop
