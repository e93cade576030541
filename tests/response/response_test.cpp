// A student's AddCollisionImpulse in the engine: built from the file (the listing's own text),
// run in a child process, and giving what the engine's own listing page gives.
#include "demos/response/response_build.h"
#include "demos/response/response_child.h"
#include "physics/listing_reference.h"
#include "physics/world.h"
#include "tests/support/response_files.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>
#include <random>

namespace impulse::workshop {
namespace {

using physics::Vec3;

// As the workshop prints it (its line numbers and wrap marks removed), listing 1 does not
// compile: one ')' too many on the line that ends eq. 13's denominator, and one closing Dot()
// early in the tangent's, which then adds a vector to a float. The compiler says so, naming the
// listing's file and lines, as it would for a student's own.
TEST(ResponseBuild, ListingAsPrintedDoesNotCompileAndTheCompilerSaysWhere) {
  try {
    build_response(test::listing("listing1_printed.cpp"));
    FAIL() << "the listing as printed compiled";
  } catch (const BuildError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("listing1_printed.cpp does not compile:"), std::string::npos) << text;
    EXPECT_NE(text.find("listing1_printed.cpp:77:"), std::string::npos) << text;   // r1) ) );
    EXPECT_NE(text.find("listing1_printed.cpp:108:"), std::string::npos) << text;  // r0) ) +
    EXPECT_EQ(text.find("impulse's call"), std::string::npos) << "an error in our wrapper, not the listing's: " << text;
  }
}

TEST(ResponseBuild, AFileWithoutTheFunctionIsRefusedBeforeCompiling) {
  const std::string path = test::scratch_file("no_function.cpp", "static void Respond() {}\n");
  try {
    build_response(path);
    FAIL() << "built";
  } catch (const BuildError& error) {
    EXPECT_NE(std::string(error.what()).find("defines no AddCollisionImpulse"), std::string::npos) << error.what();
  }
}

// The same text twice is built once: the second is the cache's, under the same name.
TEST(ResponseBuild, TheSameFileIsBuiltOnce) {
  const std::string path = test::scratch_file("cached.cpp", test::read(test::listing("listing1.cpp")) + "// cached\n");
  const BuiltResponse first = build_response(path);
  const BuiltResponse second = build_response(path);
  EXPECT_FALSE(second.compiled);
  EXPECT_EQ(first.shared_object, second.shared_object);
}

// Four builds of one new file at once (four impulses started by a course's make -j) all succeed,
// with one shared object: each compiles into a temporary of its own and renames it into place.
TEST(ResponseBuild, ConcurrentBuildsOfOneFileAllSucceed) {
  const std::string text = test::read(test::listing("listing1_corrected.cpp")) + "// built four times at once, " +
                           std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) + "\n";
  const std::string path = test::scratch_file("concurrent.cpp", text);
  std::vector<std::string> built(4);
  std::vector<std::thread> builders;
  for (size_t i = 0; i < built.size(); ++i) builders.emplace_back([&, i] { built[i] = build_response(path).shared_object; });
  for (std::thread& builder : builders) builder.join();
  for (const std::string& so : built) EXPECT_EQ(so, built.front());
  EXPECT_TRUE(std::filesystem::is_regular_file(built.front()));
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(built.front()).parent_path()))
    EXPECT_FALSE(entry.path().string().starts_with(built.front() + ".")) << "a temporary left: " << entry.path();
}

// Listing 1 with its two parentheses fixed is the engine's own listing page (workshop_listing.cpp)
// when e = 0 (the listing hard-codes it): a box tumbling onto the ground, a ball dropped on it,
// one impulse per touching contact per step, each with the 1.5 x penetration push and the
// unclamped friction. Only the listing's floats differ from the engine's doubles.
TEST(ChildResponse, ListingOneRunsAsTheEnginesListingPage) {
  const BuiltResponse built = build_response(test::listing("listing1.cpp"));
  physics::WorldSettings settings;
  settings.method = physics::ResponseMethod::workshop;
  settings.sleep.enabled = false;
  physics::World reference = test::tumbling_box_and_ball(settings);
  settings.response = child_response_maker(built.shared_object, "listing1.cpp");
  physics::World student = test::tumbling_box_and_ball(settings);
  double largest = 0;
  int touching_steps = 0;
  for (int step = 0; step < 150; ++step) {
    reference.step();
    student.step();
    touching_steps += !student.record().contacts.empty();
    for (size_t i = 0; i < reference.bodies().size(); ++i) {
      largest = std::max(largest, (reference.bodies()[i].position - student.bodies()[i].position).norm());
      largest = std::max(largest, (reference.bodies()[i].velocity - student.bodies()[i].velocity).norm());
    }
  }
  EXPECT_GT(touching_steps, 100);
  EXPECT_LT(largest, 1e-5);
  // The impulses it applied are recorded as the page's are, from the momentum they gave.
  ASSERT_EQ(reference.record().contacts.size(), student.record().contacts.size());
  for (size_t i = 0; i < reference.record().contacts.size(); ++i) {
    EXPECT_NEAR(reference.record().contacts[i].normal_impulse, student.record().contacts[i].normal_impulse, 1e-4);
    EXPECT_LT((reference.record().contacts[i].tangent_impulse - student.record().contacts[i].tangent_impulse).norm(), 1e-4);
  }
}

// The corrected listing (the pair's e above 0.5 m/s, Baumgarte's bias, Coulomb's clamp) is the
// engine's reference page, listing_reference.h: the answer a student's file is graded beside. Call
// for call, on 2000 seeded contacts between random bodies (one of them still, now and then), the
// file's velocities are the page's, but for the listing's floats.
TEST(ChildResponse, CorrectedListingIsTheEnginesReferenceCallForCall) {
  ChildResponse student(build_response(test::listing("listing1_corrected.cpp")).shared_object, "listing1_corrected.cpp");
  std::mt19937 random(27);
  int pushed = 0, clamped = 0;
  for (int call = 0; call < 2000; ++call) {
    physics::PlainBody a = test::random_body(random, false), b = test::random_body(random, call % 5 == 0);
    const physics::PlainContact contact = test::random_contact(random, a, b);
    physics::RigidBody ra = test::view(a), rb = test::view(b);
    const physics::ListingImpulse expected = physics::reference_collision_impulse(
        ra, rb, test::vec(contact.point), test::vec(contact.normal), contact.penetration, {a.restitution, a.friction, contact.time_step});
    student.respond(a, b, contact);
    pushed += expected.normal > 0;
    clamped += expected.normal > 0 && std::abs(std::abs(expected.tangent) - a.friction * expected.normal) < 1e-9;
    const double scale = 1 + ra.lin_velocity.norm() + rb.lin_velocity.norm() + ra.ang_velocity.norm() + rb.ang_velocity.norm();
    for (auto [plain, view] : {std::pair<const physics::PlainBody*, const physics::RigidBody*>{&a, &ra}, {&b, &rb}}) {
      ASSERT_LT((test::vec(plain->lin_velocity) - view->lin_velocity).norm(), 1e-5 * scale) << "call " << call;
      ASSERT_LT((test::vec(plain->ang_velocity) - view->ang_velocity).norm(), 1e-5 * scale) << "call " << call;
    }
  }
  EXPECT_GT(pushed, 500);   // the calls pushed, and
  EXPECT_GT(clamped, 100);  // friction's clamp held, often enough to tell
}

}  // namespace
}  // namespace impulse::workshop
