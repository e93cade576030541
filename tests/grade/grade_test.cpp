// The grade against the listings of assets/workshop and against responses that are wrong in one
// way each (tests/response/responses/): what each passes, what each fails, and which hint it gets.
// The engine's reference (listing 1 corrected, physics/listing_reference.h) must pass every case:
// the cases ask nothing of a student that the method itself cannot do.
#include "demos/grade/grade.h"
#include "demos/grade/listing_code.h"
#include "demos/response/response_build.h"
#include "demos/response/response_child.h"
#include "tests/support/response_files.h"

#include <gtest/gtest.h>

#include <map>

namespace impulse::workshop {
namespace {

physics::OutsideResponseMaker response_of(const std::string& path, double time_limit = kDefaultTimeLimit) {
  return child_response_maker(build_response(path).shared_object, path, time_limit);
}
std::string fixture(const std::string& name) { return std::string(IMPULSE_SOURCE_DIR) + "/tests/response/responses/" + name; }

std::map<std::string, CaseResult> by_name(const std::vector<CaseResult>& results) {
  std::map<std::string, CaseResult> map;
  for (const CaseResult& result : results) map[result.name] = result;
  return map;
}

std::string describe(const CaseResult& r) { return r.name + ": expected " + r.expected + "; measured " + r.measured + "; " + r.hint + r.failure; }

TEST(Grade, ThirteenCasesInOrder) {
  const std::vector<std::string> names = case_names();
  ASSERT_EQ(names.size(), 13u);
  EXPECT_EQ(names.front(), "head_on_equal_e0");
  EXPECT_EQ(names.back(), "stack");
}

TEST(Grade, TheEnginesReferencePassesEveryCase) {
  for (const CaseResult& result : grade({})) EXPECT_TRUE(result.passed) << describe(result);
}

// The correct solution passes every case, with the reference's very numbers (it is the same
// algorithm, in floats).
TEST(Grade, CorrectedListingPassesEveryCase) {
  const std::map<std::string, CaseResult> reference = by_name(grade({}));
  for (const CaseResult& result : grade(response_of(test::listing("listing1_corrected.cpp")))) {
    EXPECT_TRUE(result.passed) << describe(result);
    EXPECT_EQ(result.expected, reference.at(result.name).expected) << result.name;
  }
}

// Listing 1 with its parentheses fixed passes the two hits at e = 0 alone: it hard-codes e = 0,
// pushes by 1.5 x penetration (heavy bodies sink) and never clamps friction. Its friction is right
// where it sticks, but the ball with backspin does not bounce (e = 0), and is told so.
TEST(Grade, ListingOnePassesOnlyTheHitsAtEZero) {
  const std::string listing = test::listing("listing1.cpp");
  const std::map<std::string, CaseResult> results = by_name(grade(response_of(listing), "", response_source(listing)));
  for (const auto& [name, result] : results)
    EXPECT_EQ(result.passed, name == "head_on_equal_e0" || name == "head_on_unequal_e0") << describe(result);
  EXPECT_NE(results.at("head_on_equal_e0.7").hint.find("line 71"), std::string::npos) << describe(results.at("head_on_equal_e0.7"));
  EXPECT_NE(results.at("head_on_unequal_e1").hint.find("line 71"), std::string::npos);
  // The hack fix named where this file has it: its line 82 (the printed listing's line 85).
  EXPECT_NE(results.at("ball_rest").hint.find("your line 82, the listing's hack fix"), std::string::npos) << describe(results.at("ball_rest"));
  EXPECT_NE(results.at("stack").hint.find("your line 82, the listing's hack fix"), std::string::npos) << describe(results.at("stack"));
  EXPECT_NE(results.at("slide_friction").hint.find("clamp"), std::string::npos) << describe(results.at("slide_friction"));
  EXPECT_NE(results.at("slide_frictionless").hint.find("clamp"), std::string::npos);
  EXPECT_NE(results.at("bounce_spin").measured.find("no bounce"), std::string::npos) << describe(results.at("bounce_spin"));
  EXPECT_NE(results.at("bounce_spin").hint.find("line 71"), std::string::npos) << describe(results.at("bounce_spin"));
}

// The ball with backspin leaves rolling, the contact point's sliding stopped (it takes less than
// mu Jn), as the corrected listing and the reference have it; the law's numbers are Coulomb's.
TEST(Grade, CorrectedListingLeavesTheSpinningBallRolling) {
  const CaseResult result = grade(response_of(test::listing("listing1_corrected.cpp")), "bounce_spin").front();
  EXPECT_TRUE(result.passed) << describe(result);
  EXPECT_NE(result.expected.find("vx' 0.857 m/s, wz' -3.43 rad/s"), std::string::npos) << describe(result);
  EXPECT_NE(result.expected.find("it rolls, Jt 1.14 N s <= mu Jn 2.21 N s"), std::string::npos) << describe(result);
}

// Eq. 8 as printed, -(1 - e): right at e = 0, and at e = 0.7 and 1 the pair goes on closing (and
// the ball with backspin goes on falling into the ground).
TEST(Grade, PrintedSignFailsTheBouncesWithEqEightsHint) {
  const std::map<std::string, CaseResult> results = by_name(grade(response_of(fixture("printed_sign.cpp"))));
  for (const char* name : {"head_on_equal_e0", "head_on_unequal_e0", "ball_rest", "slide_friction", "slide_frictionless", "stack"})
    EXPECT_TRUE(results.at(name).passed) << describe(results.at(name));
  for (const char* name : {"head_on_equal_e0.7", "head_on_equal_e1", "head_on_unequal_e0.7", "head_on_unequal_e1", "bounce_spin"}) {
    EXPECT_FALSE(results.at(name).passed) << name;
    EXPECT_NE(results.at(name).hint.find("-(1 - e)"), std::string::npos) << describe(results.at(name));
  }
}

// Friction not clamped: the oblique hit takes more than mu Jn, the sliding box stops at once, and
// the frictionless one too. The ball with backspin passes: stopping its contact point takes less
// than mu Jn, so the clamp does not bind.
TEST(Grade, UnclampedFrictionFailsCoulombsCases) {
  const std::map<std::string, CaseResult> results = by_name(grade(response_of(fixture("no_clamp.cpp"))));
  for (const char* name : {"oblique", "slide_friction", "slide_frictionless"}) {
    EXPECT_FALSE(results.at(name).passed) << name;
    EXPECT_NE(results.at(name).hint.find("clamp"), std::string::npos) << describe(results.at(name));
  }
  for (const char* name : {"head_on_equal_e0.7", "head_on_unequal_e1", "off_centre_spin", "ball_rest", "bounce_spin"})
    EXPECT_TRUE(results.at(name).passed) << describe(results.at(name));
}

// A hint follows what went wrong in the run, not the case: without friction the top box of the
// stack slides off (and the hint says friction, not the hack fix the file does not have); without
// any position correction the resting balls sink and are never pushed back (not a jiggle), and so
// does the stack.
TEST(Grade, HintsFollowTheCauseMeasuredInTheRun) {
  const std::string no_friction = fixture("no_friction.cpp");
  const std::map<std::string, CaseResult> slid = by_name(grade(response_of(no_friction), "", response_source(no_friction)));
  const CaseResult& stack = slid.at("stack");
  EXPECT_FALSE(stack.passed);
  EXPECT_NE(stack.hint.find("slid off with no friction holding it"), std::string::npos) << describe(stack);
  EXPECT_EQ(stack.hint.find("hack fix"), std::string::npos) << describe(stack);
  EXPECT_NE(stack.measured.find("sunk 2."), std::string::npos) << "the top's depth is measured only in what holds it: " << describe(stack);

  const std::string uncorrected = fixture("no_position_correction.cpp");
  const std::map<std::string, CaseResult> sank = by_name(grade(response_of(uncorrected), "", response_source(uncorrected)));
  for (const char* name : {"ball_rest", "stack"}) {
    const CaseResult& result = sank.at(name);
    EXPECT_FALSE(result.passed) << name;
    EXPECT_NE(result.hint.find("the penetration is never corrected"), std::string::npos) << describe(result);
    EXPECT_EQ(result.hint.find("hack fix"), std::string::npos) << describe(result);
    EXPECT_EQ(result.hint.find("jiggle"), std::string::npos) << describe(result);
  }
}

// The hack fix is found as the student wrote it, in C++ or Python, on its own line; a correction
// through a division, a comment, or a penetration not added to jn is not it.
TEST(ListingCode, TheHackFixIsFoundOnTheStudentsLine) {
  EXPECT_EQ(hack_fix_line("a\nb\njn = jn + (penetration*1.5f);\n"), 3);
  EXPECT_EQ(hack_fix_line("x\n    jn += 1.5f * penetration;  // stop sinking\n"), 2);
  EXPECT_EQ(hack_fix_line("def f():\n    jn += penetration * 1.5  # hack\n"), 2);
  EXPECT_EQ(hack_fix_line("jn = jn + beta / TimeStep() * depth / normDiv;\njn += beta / dt * penetration / normDiv;\n"), 0);
  EXPECT_EQ(hack_fix_line("// jn = jn + (penetration*1.5f);\n# jn += penetration * 1.5\n"), 0);
  EXPECT_EQ(hack_fix_line("float depth = penetration * 1.5f;\n"), 0);
}

// A crash ends the case with the report (the signal, the step, the bodies), never the grade.
TEST(Grade, ACrashFailsTheCaseWithItsReport) {
  const CaseResult result = grade(response_of(fixture("crash.cpp")), "head_on_equal_e0").front();
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.failure.find("crash.cpp: AddCollisionImpulse"), std::string::npos) << result.failure;
  // Crashed by SIGSEGV; under AddressSanitizer the child reports it and exits instead.
  EXPECT_TRUE(result.failure.find("SIGSEGV") != std::string::npos || result.failure.find("exit code") != std::string::npos) << result.failure;
  EXPECT_NE(result.failure.find("at step 11 (t = 0.1833 s), the contact of 'a' and 'b'"), std::string::npos) << result.failure;
}

TEST(Grade, AnEndlessLoopIsStoppedAtTheTimeLimit) {
  const CaseResult result = grade(response_of(fixture("endless_loop.cpp"), 0.3), "oblique").front();
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.failure.find("did not return within 0.3 s"), std::string::npos) << result.failure;
  EXPECT_NE(result.hint.find("never returned"), std::string::npos) << result.hint;
}

TEST(Grade, ANaNIsReportedWhereDbgCheckVectorFindsIt) {
  const CaseResult result = grade(response_of(fixture("zero_tangent.cpp")), "head_on_unequal_e1").front();
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.failure.find("zero_tangent.cpp:10: DBG_CHECKVECTOR( c0.m_linVelocity )"), std::string::npos) << result.failure;
  EXPECT_NE(result.hint.find("zero vector normalised"), std::string::npos) << result.hint;
}

// --only names one case exactly: "e0" is no case, and "head_on_equal_e0" is not "..._e0.7".
TEST(Grade, OnlyTakesAnExactName) {
  const std::vector<CaseResult> one = grade({}, "head_on_equal_e0");
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one.front().name, "head_on_equal_e0");
  EXPECT_THROW(grade({}, "e0"), std::invalid_argument);
  EXPECT_THROW(grade({}, "head_on_equal"), std::invalid_argument);
}

}  // namespace
}  // namespace impulse::workshop
