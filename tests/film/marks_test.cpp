// Busy frames (marks.h): only the strongest pairs are marked, each pair's points as one mark.
#include "demos/film/film.h"
#include "demos/film/marks.h"
#include "demos/film/scene_draw_list.h"
#include "demos/film/world_take.h"
#include "tests/support/scene_scratch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace impulse {
namespace {

physics::ContactRecord contact(int a, int b, double x, double impulse) {
  physics::ContactRecord record;
  record.body_a = a;
  record.body_b = b;
  record.point = physics::Vec3(x, 0, 0);
  record.normal_impulse = impulse;
  record.tangent_impulse = physics::Vec3(0, 0, impulse / 10);
  return record;
}

// Busy frames: the strongest pairs only, each pair's points as one mark with their total impulse
// at their impulse-weighted centre; a frame within the limit keeps every point.
TEST(MarkedContacts, ABusyFrameKeepsTheStrongestPairsEachAsOneMark) {
  const std::vector<physics::ContactRecord> contacts{
      contact(1, 0, 0.0, 1.0), contact(1, 0, 1.0, 3.0),  // pair (1, 0): 4 N s centred at x = 0.75
      contact(2, 0, 5.0, 0.5),                            // the weakest pair
      contact(3, 2, 7.0, 2.0), contact(4, 3, 9.0, 6.0)};
  EXPECT_EQ(demos::marked_contacts(contacts, 4).size(), 5u) << "four pairs: nothing to merge";
  EXPECT_EQ(demos::marked_contacts(contacts, 0).size(), 5u) << "no limit";
  const std::vector<physics::ContactRecord> marked = demos::marked_contacts(contacts, 3);
  ASSERT_EQ(marked.size(), 3u);
  EXPECT_EQ(marked[0].body_a, 1);
  EXPECT_DOUBLE_EQ(marked[0].normal_impulse, 4.0);
  EXPECT_DOUBLE_EQ(marked[0].point.x(), 0.75);
  EXPECT_DOUBLE_EQ(marked[0].tangent_impulse.z(), 0.4);
  EXPECT_EQ(marked[1].body_a, 3);
  EXPECT_EQ(marked[2].body_a, 4);
  EXPECT_DOUBLE_EQ(marked[2].normal_impulse, 6.0);
}

// A contact's dot keeps to the bodies it marks: at most a quarter of the smaller body's size (a
// sphere's radius, a box's smallest half-size; a plane has none), over the renderer's 4 pixels.
TEST(ContactDots, AreAtMostAQuarterOfTheSmallerBody) {
  std::vector<physics::Body> bodies(3);
  bodies[0].shape = physics::Shape::plane(physics::Vec3::UnitY(), 0);
  bodies[1].shape = physics::Shape::box(physics::Vec3(0.5, 0.1, 0.3));
  bodies[2].shape = physics::Shape::sphere(0.06);
  const std::vector<physics::ContactRecord> contacts{contact(1, 0, 0.0, 1.0), contact(2, 1, 0.2, 1.0), contact(2, 0, 1.0, 1.0)};
  const demos::Scene scene;
  const render::DrawList list =
      demos::scene_draw_list(scene, bodies, demos::poses_of(bodies), {}, contacts, demos::ArrowScales{}, render::Camera{});
  ASSERT_EQ(list.points.size(), 3u);
  const float expected[3] = {0.25f * 0.1f, 0.25f * 0.06f, 0.25f * 0.06f};  // box on ground, ball on box, ball on ground
  for (int i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(list.points[size_t(i)].largest_radius, expected[i]) << "contact " << i;
    EXPECT_FLOAT_EQ(list.points[size_t(i)].radius_pixels, 4.0f) << "contact " << i;
  }
}

// A contact's normal is drawn the way the impulse arrow drawn at it pushes: for a box on the ground
// both point up, whichever body the contact names first; between two moving bodies, A's way.
TEST(ContactNormals, PointTheWayTheDrawnImpulsePushes) {
  std::vector<physics::Body> bodies(3);
  bodies[0].shape = physics::Shape::plane(physics::Vec3::UnitY(), 0);
  bodies[0].inv_mass = 0;  // the ground: static
  bodies[1].shape = physics::Shape::box(physics::Vec3(0.5, 0.1, 0.3));
  bodies[2].shape = physics::Shape::sphere(0.1);
  bodies[1].inv_mass = bodies[2].inv_mass = 1;  // the box and the ball move
  for (const bool ground_first : {true, false}) {
    physics::ContactRecord on_ground = ground_first ? contact(0, 1, 0.0, 1.0) : contact(1, 0, 0.0, 1.0);
    on_ground.normal = physics::Vec3(0, ground_first ? -1 : 1, 0);  // the way A must move
    physics::ContactRecord ball_on_box = contact(2, 1, 0.2, 0.5);
    ball_on_box.normal = physics::Vec3::UnitY();
    const demos::Scene scene;
    const render::DrawList list = demos::scene_draw_list(scene, bodies, demos::poses_of(bodies), {}, {on_ground, ball_on_box},
                                                         demos::ArrowScales{}, render::Camera{});
    std::vector<render::Vec3f> normals, impulses;
    for (const render::ArrowItem& arrow : list.arrows) {
      const auto same = [&](const render::Colour& c) { return arrow.colour.r == c.r && arrow.colour.g == c.g && arrow.colour.b == c.b; };
      if (same(demos::mark_colour::contact_normal)) normals.push_back(arrow.direction);
      if (same(demos::mark_colour::normal_impulse)) impulses.push_back(arrow.direction);
    }
    ASSERT_EQ(normals.size(), 2u);
    ASSERT_EQ(impulses.size(), 3u);  // the box's on the ground; the ball's and the box's between them
    EXPECT_GT(normals[0].y(), 0) << "ground first: " << ground_first;
    EXPECT_GT(impulses[0].y(), 0) << "ground first: " << ground_first;
    EXPECT_GT(normals[1].dot(impulses[1]), 0) << "the ball's (A's) push and the normal agree";
  }
}

// The legend names the sleeping look in a film where a moving body falls asleep, and only there: a
// ball dropped onto the ground sleeps within its 2 s with [world] sleeping on, and never with it off.
TEST(Legend, NamesTheSleepingLookWhereABodyFallsAsleep) {
  const std::filesystem::path dir = testing::scratch("marks_test", "asleep");
  auto take_of = [&](bool sleeping) {
    const demos::Scene scene = testing::scene_from(dir, std::string("[scene]\nduration = 2.0\n[world]\nsleeping = ") +
                                                            (sleeping ? "true" : "false") +
                                                            "\n[[body]]\nname = \"ground\"\nshape = \"plane\"\n"
                                                            "[[body]]\nname = \"ball\"\nshape = \"sphere\"\nradius = 0.2\n"
                                                            "position = [0, 0.5, 0]\nrestitution = 0\n");
    demos::WorldTake take(scene);
    while (!take.finished()) take.step();
    return std::make_pair(scene, take.summary().someone_sleeps);
  };
  const auto [asleep_scene, sleeps] = take_of(true);
  const auto [awake_scene, sleeps_without] = take_of(false);
  EXPECT_TRUE(sleeps);
  EXPECT_FALSE(sleeps_without);
  const render::CameraView camera = render::make_camera_view(render::Camera{}, 1280, 720);
  auto names_it = [&](const demos::Scene& scene, bool someone_sleeps) {
    const std::vector<render::LegendEntry> entries = demos::legend(scene.draw, demos::ArrowScales{}, camera, render::Vec3f(0, 1, 0), someone_sleeps);
    return std::count_if(entries.begin(), entries.end(), [](const render::LegendEntry& e) { return e.asleep && e.text.find("asleep") != std::string::npos; });
  };
  EXPECT_EQ(names_it(asleep_scene, sleeps), 1);
  EXPECT_EQ(names_it(awake_scene, sleeps_without), 0);
  demos::Scene plain = asleep_scene;
  plain.draw.sleeping = false;  // sleeping bodies drawn as any other: nothing to name
  EXPECT_EQ(names_it(plain, true), 0);
}

}  // namespace
}  // namespace impulse
