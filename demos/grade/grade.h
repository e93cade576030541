// `impulse grade`: a student's AddCollisionImpulse held to the laws, one small scene per law.
//
// Each case is a scene (grade_cases.cpp) that the response moves, and a judge that measures what a
// law says of it: the parting speed of eq. 5 and the momentum of eq. 7 in head-on hits, the
// angular momentum of eq. 12 in an off-centre one, Coulomb's law in an oblique hit and on a
// sliding box, a resting ball that neither jiggles nor sinks, a stack that stands. Its expectation
// holds for the engine's reference (listing 1 corrected, physics/listing_reference.h), which is
// called exactly as the student's function is, and its hint, when it fails, is in the workshop's
// words. A case whose response crashes, loops or makes a NaN fails with that report.
#pragma once
#include "demos/scene/scene.h"
#include "physics/outside_response.h"

#include <string>
#include <vector>

namespace impulse::workshop {

struct CaseResult {
  std::string name;      // "head_on_equal_e0.7": what --only takes
  std::string title;     // "head on, equal masses, e = 0.7"
  std::string law;       // "eq. 5 and 7: they part at e times the speed they met; momentum kept"
  std::string expected;  // what the law gives here, in numbers
  std::string measured;  // what the response did
  bool passed = false;
  std::string hint;      // why it may have failed, in the workshop's words (empty when passed)
  std::string failure;   // the response crashed, looped or made a NaN: the report (the case failed)
};

// Every case's name, in the order they run.
std::vector<std::string> case_names();

// The scene of case `name` with the given response ("" for the engine's reference page; else a
// response file's path, as `[world] response` takes it), as render and compare draw it. Throws
// std::invalid_argument for an unknown name, naming the known ones.
demos::Scene case_scene(const std::string& name);

// Runs case `name` with `response` (empty: the engine's reference page) and judges it. `source`:
// the text of the response's file, so that a hint names its lines where it holds the listing's code.
CaseResult grade_case(const std::string& name, const physics::OutsideResponseMaker& response, const std::string& source = "");

// Every case, or the one named `only` (exactly), in order.
std::vector<CaseResult> grade(const physics::OutsideResponseMaker& response, const std::string& only = "", const std::string& source = "");

// The text of a response's file, for grade()'s `source` ("" where it cannot be read).
std::string response_source(const std::string& path);

}  // namespace impulse::workshop
