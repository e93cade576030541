// --set KEY=VALUE written into a scene's TOML (demos/scene/scene_overrides.h), directly: the node
// each argument writes and names, lists chosen by index or name, tables made where missing, a
// bare word taken as a string, and each malformed argument refused naming itself.
#include "demos/scene/scene_error.h"
#include "demos/scene/scene_overrides.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace impulse::demos {
namespace {

toml::table scene_tables() {
  return toml::parse(R"(
[world]
friction = true
[[body]]
name = "ball"
restitution = 0.5
[[body]]
name = "box"
mass = 1
)");
}

// The message apply_overrides refuses `setting` with, or "" when it takes it.
std::string refusal(const std::string& setting) {
  toml::table root = scene_tables();
  try {
    apply_overrides(root, {setting});
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(Overrides, EachArgumentWritesOneNodeAndNamesIt) {
  toml::table root = scene_tables();
  const WrittenNodes written = apply_overrides(
      root, {"world.friction=false", "body[ball].restitution=0.2", "body[1].mass=2", "camera.position=[0, 2, 8]"});
  EXPECT_EQ(root["world"]["friction"].value<bool>(), false);
  EXPECT_EQ(root["body"][0]["restitution"].value<double>(), 0.2);
  EXPECT_EQ(root["body"][1]["mass"].value<int64_t>(), 2);
  ASSERT_TRUE(root["camera"]["position"].is_array());  // [camera] made where the file has none
  EXPECT_EQ(root["camera"]["position"][2].value<int64_t>(), 8);
  EXPECT_EQ(written.size(), 4u);
  EXPECT_EQ(written.at(root["world"]["friction"].node()), "--set world.friction=false");
  EXPECT_EQ(written.at(root["body"][0]["restitution"].node()), "--set body[ball].restitution=0.2");
}

TEST(Overrides, ABareWordIsAStringAndAQuotedOneTheSame) {
  toml::table root = scene_tables();
  apply_overrides(root, {"world.method=projection", "body[box].colour=\"#ff0000\""});
  EXPECT_EQ(root["world"]["method"].value<std::string>(), "projection");
  EXPECT_EQ(root["body"][1]["colour"].value<std::string>(), "#ff0000");
}

TEST(Overrides, AMalformedArgumentIsRefusedNamingItself) {
  EXPECT_EQ(refusal("world.friction"), "--set world.friction: expected KEY=VALUE, like world.friction=false or "
                                       "body[ball].restitution=0.2");
  EXPECT_EQ(refusal("friction=false"), "--set friction=false: KEY names a field of a table, like world.friction");
  EXPECT_EQ(refusal("wrld.friction=false"), "--set wrld.friction=false: a scene has no table 'wrld'; did you mean 'world'?");
  EXPECT_EQ(refusal("body.mass=2"), "--set body.mass=2: [[body]] is a list: choose one, like body[0]");
  EXPECT_EQ(refusal("body[2].mass=2"), "--set body[2].mass=2: there are 2 [[body]] tables, numbered from 0");
  EXPECT_EQ(refusal("body[bal].mass=2"),
            "--set body[bal].mass=2: no [[body]] is named 'bal'; did you mean 'ball'? (named: 'ball', 'box')");
  EXPECT_EQ(refusal("world[0].friction=false"), "--set world[0].friction=false: 'world' is a table, not a list: no [0]");
  EXPECT_EQ(refusal("body[box].mass=1\nrestitution=5"),
            "--set body[box].mass=1\\nrestitution=5: a value is one line, and a line break follows '1'; give each "
            "field its own --set");
  EXPECT_NE(refusal("body[box].mass=1 2").find("cannot read the value '1 2'"), std::string::npos);
  EXPECT_EQ(refusal("body[box].mass=3"), "");
}

TEST(Overrides, DidYouMeanOffersOnlyAClosePeer) {
  EXPECT_EQ(did_you_mean("frictoin", {"friction", "restitution"}), "did you mean 'friction'?");
  EXPECT_EQ(did_you_mean("mass", {"friction", "restitution"}), "");
}

}  // namespace
}  // namespace impulse::demos
