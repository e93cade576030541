// Comparisons of a varied restitution or friction (demos/scene/scene_compare.h): a pane whose value
// the pairs' mixing overrides is warned about with the reason, and a comparison whose panes all meet
// with the same materials is refused; one whose values show is neither.
#include "demos/scene/scene_compare.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace impulse::demos {
namespace {

// A pendulum-like bob and a block on the ground, the bob's restitution varied over `values`; the
// block's restitution `block_e`, the ground's the default 0.5 unless `ground_e` is given.
std::string bob_scene(const std::string& values, const std::string& block_e, const std::string& ground_e = "",
                      const std::string& extra = "") {
  return "[compare]\nvary = \"body[bob].restitution\"\nvalues = " + values +
         "\n[[body]]\nname = \"ground\"\nshape = \"plane\"\n" + (ground_e.empty() ? "" : "restitution = " + ground_e + "\n") +
         "[[body]]\nname = \"bob\"\nshape = \"sphere\"\nradius = 0.1\nposition = [0, 1, 0]\n" +
         "[[body]]\nname = \"block\"\nshape = \"box\"\nsize = [0.2, 0.2, 0.2]\nposition = [1, 0.1, 0]\nrestitution = " + block_e + "\n" + extra;
}

struct Loaded {
  std::string error;
  std::vector<std::string> warnings;
};

Loaded load(const std::string& text) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "compare_test.toml";
  std::ofstream(path) << text;
  Loaded loaded;
  try {
    const SceneFile file(path.string());
    const Scene scene = file.scene();
    loaded.warnings = compare_warnings(load_variants(file, {}, scene.compare), scene.compare);
  } catch (const SceneError& error) {
    loaded.error = error.what();
  }
  return loaded;
}

TEST(CompareMaterials, APaneWhoseRestitutionThePairOverridesIsNamedWithTheReason) {
  // Pane 1's bob (e = 0) bounces with the ground's and the block's 0.5; pane 2's (e = 1) with 1.
  const Loaded loaded = load(bob_scene("[0.0, 1.0]", "0.5"));
  ASSERT_EQ(loaded.error, "");
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_NE(loaded.warnings[0].find("pane 1 (body[bob].restitution = 0.0): 'bob' bounces with 0.5 at least, not 0"), std::string::npos)
      << loaded.warnings[0];
  EXPECT_NE(loaded.warnings[0].find("a pair takes the larger of its two restitutions"), std::string::npos);
  EXPECT_NE(loaded.warnings[0].find("[[material_pair]]"), std::string::npos);
}

TEST(CompareMaterials, PanesThatAllMeetWithTheSameMaterialsAreRefused) {
  const Loaded loaded = load(bob_scene("[0.0, 0.3]", "0.5"));
  EXPECT_NE(loaded.error.find("every pane meets with the same materials, so the comparison would show nothing"), std::string::npos)
      << loaded.error;
  EXPECT_NE(loaded.error.find("the larger restitution of the two"), std::string::npos) << loaded.error;
  // A [[material_pair]] that fixes every pair's restitution hides any value too.
  const std::string pairs =
      "[[material_pair]]\nbetween = [\"rubber\", \"rubber\"]\nrestitution = 0.8\n";
  std::string text = bob_scene("[0.9, 1.0]", "0.5", "0.5", pairs);
  for (const char* body : {"name = \"ground\"\n", "name = \"bob\"\n", "name = \"block\"\n"})
    text.replace(text.find(body), std::string(body).size(), std::string(body) + "material = \"rubber\"\n");
  const Loaded paired = load(text);
  EXPECT_NE(paired.error.find("a [[material_pair]] sets what 'bob' meets"), std::string::npos) << paired.error;
}

TEST(CompareMaterials, ValuesThatShowNeedNoWarning) {
  // Every other body at 0: the bob's own restitution is what every pair bounces with.
  const Loaded loaded = load(bob_scene("[0.2, 0.8]", "0.0", "0.0"));
  EXPECT_EQ(loaded.error, "");
  EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
  // A friction varied against the default 0.5 shows through the geometric mean.
  std::string text = bob_scene("[0.2, 0.8]", "0.5");
  text.replace(text.find("restitution\""), std::string("restitution\"").size(), "friction\"");
  const Loaded friction = load(text);
  EXPECT_EQ(friction.error, "");
  EXPECT_TRUE(friction.warnings.empty());
  // [world] friction switches every contact's friction: not a material, nothing to warn about.
  std::string world = bob_scene("[false, true]", "0.5");
  world.replace(world.find("body[bob].restitution"), std::string("body[bob].restitution").size(), "world.friction");
  const Loaded switched = load(world);
  EXPECT_EQ(switched.error, "");
  EXPECT_TRUE(switched.warnings.empty());
}

// A caption may belong to one pane (pane = N) or name each pane's value and label ({value},
// {label}): each pane keeps its own, marked to be drawn inside it, and the frame's (the others)
// stay as they are; a number reads as the file wrote it (0.2, not 0.20000000000000001).
TEST(CompareCaptions, EachPaneKeepsItsOwnWithItsValueAndLabel) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "compare_captions_test.toml";
  std::ofstream(path) << bob_scene("[0.2, 0.9]", "0.1", "0.1") +
                             "[[caption]]\ntext = \"e = {value} ({label})\"\n"
                             "[[caption]]\ntext = \"only the second\"\npane = 2\n"
                             "[[caption]]\ntext = \"every pane\"\n"
                             "[[equation]]\ntex = 'e = 0.9'\npane = 2\n"
                             "[[equation]]\ntex = 'e = {value}, {label}'\n";
  const SceneFile file(path.string());
  const Scene scene = file.scene();
  ASSERT_EQ(scene.compare.values, (std::vector<std::string>{"0.2", "0.9"}));
  const std::vector<Scene> panes = load_variants(file, {}, scene.compare);
  ASSERT_EQ(panes.size(), 2u);
  ASSERT_EQ(panes[0].captions.size(), 2u);
  EXPECT_EQ(panes[0].captions[0].text, "e = 0.2 (body[bob].restitution = 0.2)");
  EXPECT_TRUE(panes[0].captions[0].own);
  EXPECT_EQ(panes[0].captions[1].text, "every pane");
  EXPECT_FALSE(panes[0].captions[1].own);
  ASSERT_EQ(panes[1].captions.size(), 3u);
  EXPECT_EQ(panes[1].captions[0].text, "e = 0.9 (body[bob].restitution = 0.9)");
  EXPECT_EQ(panes[1].captions[1].text, "only the second");
  EXPECT_TRUE(panes[1].captions[1].own);
  EXPECT_FALSE(panes[1].captions[2].own);
  // An equation of one pane is that pane's alone; one naming the value and label gets each pane's,
  // the label as LaTeX text (its brackets and underscores written as themselves).
  ASSERT_EQ(panes[0].equations.size(), 1u);
  EXPECT_EQ(panes[0].equations[0].tex, "e = 0.2, \\text{body[bob].restitution = 0.2}");
  ASSERT_EQ(panes[1].equations.size(), 2u);
  EXPECT_EQ(panes[1].equations[0].tex, "e = 0.9");
  EXPECT_EQ(panes[1].equations[1].tex, "e = 0.9, \\text{body[bob].restitution = 0.9}");
}

}  // namespace
}  // namespace impulse::demos
