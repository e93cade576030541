// Scene files: good ones load, bad ones are refused with file, line, field and reason.
#include "demos/scene/rotation_degrees.h"
#include "demos/scene/scene_file.h"
#include "demos/scene/scene_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <fstream>

namespace impulse::demos {
namespace {

std::string write_scene(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("impulse_scene_test_" + name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& text) {
  const std::string path = write_scene(::testing::UnitTest::GetInstance()->current_test_info()->name(), text);
  try {
    load_scene(path);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SceneFile, LoadsTheBounceScene) {
  const Scene scene = load_scene(std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/bounce.toml");
  ASSERT_EQ(scene.bodies.size(), 4u);
  EXPECT_EQ(scene.bodies[0].shape.type, physics::ShapeType::plane);
  EXPECT_EQ(scene.bodies[1].name, "dropped ball");
  EXPECT_DOUBLE_EQ(scene.bodies[1].material.restitution, 0.7);
  EXPECT_DOUBLE_EQ(scene.world.time_step, 1.0 / 60);
  EXPECT_EQ(scene.video.width, 1280);
  EXPECT_EQ(scene.video.fps, 30);
}

// [[body]] inertia: "solid" (the default), "hollow" or three moments; [overlay] plot_body: one
// name or several, each a body's, in the file's order.
TEST(SceneFile, InertiaAndPlotBodiesAreRead) {
  const Scene scene = load_scene(write_scene("inertia", R"([[body]]
name = "solid"
shape = "sphere"
[[body]]
name = "shell"
shape = "sphere"
inertia = "hollow"
[[body]]
name = "given"
shape = "box"
inertia = [0.1, 0.2, 0.25]
[overlay]
plots = ["speed"]
plot_body = ["shell", "solid"]
)"));
  ASSERT_EQ(scene.bodies.size(), 3u);
  EXPECT_EQ(scene.bodies[0].spread, physics::MassSpread::solid);
  EXPECT_TRUE(scene.bodies[0].principal_inertia.isZero());
  EXPECT_EQ(scene.bodies[1].spread, physics::MassSpread::hollow);
  EXPECT_EQ(scene.bodies[2].principal_inertia, physics::Vec3(0.1, 0.2, 0.25));
  EXPECT_EQ(scene.overlay.plot_bodies, (std::vector<std::string>{"shell", "solid"}));
  const physics::World world = build_world(scene);
  EXPECT_NEAR(world.bodies()[1].inertia_local(0, 0) / world.bodies()[0].inertia_local(0, 0), 5.0 / 3, 1e-12);
  EXPECT_EQ(world.bodies()[2].inertia_local(2, 2), 0.25);
  const std::string number = error_of("[[body]]\nshape = \"sphere\"\ninertia = 3\n");
  EXPECT_NE(number.find(":3: [[body]] 'body 1' field 'inertia': must be \"solid\", \"hollow\""), std::string::npos) << number;
}

TEST(SceneFile, SyntaxErrorNamesFileAndLine) {
  const std::string error = error_of("[world]\ngravity = [0, -9.81, 0]\nstep_rate = = 60\n");
  EXPECT_NE(error.find("SyntaxErrorNamesFileAndLine.toml:3:"), std::string::npos) << error;
}

TEST(SceneFile, ImpossibleValueNamesLineFieldAndReason) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\n\n[[body]]\nname = \"bad\"\nshape = \"sphere\"\nradius = 0\n");
  EXPECT_NE(error.find(":7: [[body]] 'bad' field 'radius': must be > 0 and <= 1000, got 0"), std::string::npos) << error;
}

TEST(SceneFile, NegativeMassIsRefused) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\nmass = -2\n");
  EXPECT_NE(error.find("field 'mass': must be > 0 and <= 1e+09, got -2"), std::string::npos) << error;
}

TEST(SceneFile, RestitutionAboveOneIsRefused) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\nrestitution = 1.5\n");
  EXPECT_NE(error.find("field 'restitution': must be >= 0 and <= 1, got 1.5"), std::string::npos) << error;
}

TEST(SceneFile, UnknownFieldIsNamed) {
  const std::string error = error_of("[[body]]\nshape = \"sphere\"\nradiuss = 1\n");
  EXPECT_NE(error.find(":3: [[body]] 'body 1' field 'radiuss': unknown field"), std::string::npos) << error;
}

TEST(SceneFile, WrongTypeIsNamed) {
  const std::string error = error_of("[camera]\nposition = [0, 1]\n[[body]]\nshape = \"sphere\"\n");
  EXPECT_NE(error.find(":2: [camera] field 'position': must be an array of three numbers"), std::string::npos) << error;
}

TEST(SceneFile, MissingFileIsReported) {
  try {
    load_scene("/nonexistent/scene.toml");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.toml"), std::string::npos) << error.what();
  }
}

TEST(SceneFile, NoBodiesIsRefused) {
  EXPECT_NE(error_of("[world]\nsubsteps = 4\n").find("no bodies"), std::string::npos);
}

Scene scene_of(const std::string& text, const std::vector<std::string>& settings = {}) {
  return load_scene(write_scene(::testing::UnitTest::GetInstance()->current_test_info()->name(), text), settings);
}

// `rotation` is degrees about x, then y, then z, each about the world axis, right-handed: a
// positive angle turns counter-clockwise seen from the axis's tip, looking toward the origin.
// TOML reads \t, \f, \r, \n and \b in double quotes as escapes: LaTeX so written is refused with
// the advice to use single quotes, and single-quoted LaTeX, on one line or several, loads as written.
TEST(SceneFile, LatexInDoubleQuotesIsRefusedWithTheAdviceToUseSingleQuotes) {
  const std::string body = "[[body]]\nshape = \"sphere\"\n[[equation]]\n";
  for (const char* tex : {"\"\\frac{1}{2}\"", "\"x = 1, \\nu = 3\"", "\"\\rho\"", "\"\\beta\"", "\"\"\"\n\\theta\"\"\""}) {
    const std::string error = error_of(body + "tex = " + tex + "\n");
    EXPECT_NE(error.find(":4: [[equation]] 1 field 'tex': TOML read \\"), std::string::npos) << tex << ": " << error;
    EXPECT_NE(error.find("write LaTeX in single quotes, tex = '\\theta'"), std::string::npos) << tex << ": " << error;
  }
  EXPECT_NE(error_of(body + "tex = \"\\alpha\"\n").find("write LaTeX in single quotes, tex = '\\alpha'"), std::string::npos);
  const std::string path = write_scene("single_quoted_latex", body + "tex = '\\theta = \\frac{1}{2}'\n[[equation]]\ntex = \'\'\'\n\\rho\n\\nu\n\'\'\'\n");
  const Scene scene = load_scene(path);
  ASSERT_EQ(scene.equations.size(), 2u);
  EXPECT_EQ(scene.equations[0].tex, "\\theta = \\frac{1}{2}");
  EXPECT_EQ(scene.equations[1].tex, "\\rho\n\\nu\n");
}

TEST(SceneFile, RotationTurnsAboutWorldXThenYThenZRightHanded) {
  const Scene quarter = scene_of("[[body]]\nshape = \"box\"\nrotation = [0, 0, 90]\n");
  const physics::Quat z = quarter.bodies[0].orientation;
  EXPECT_TRUE((z * physics::Vec3::UnitX()).isApprox(physics::Vec3::UnitY(), 1e-12)) << (z * physics::Vec3::UnitX()).transpose();
  // x first, then y: the body's y axis goes to world +z (x turn), then to world +x (y turn).
  const Scene both = scene_of("[[body]]\nshape = \"box\"\nrotation = [90, 90, 0]\n");
  const physics::Quat q = both.bodies[0].orientation;
  EXPECT_TRUE((q * physics::Vec3::UnitY()).isApprox(physics::Vec3::UnitX(), 1e-12)) << (q * physics::Vec3::UnitY()).transpose();
  EXPECT_TRUE((q * physics::Vec3::UnitZ()).isApprox(-physics::Vec3::UnitY(), 1e-12)) << (q * physics::Vec3::UnitZ()).transpose();
}

// sin and cos without libm (the same bits on every machine): exact at multiples of 90 degrees,
// within 1e-15 of std::sin and std::cos elsewhere (their angle taken within 180 degrees first, as
// radians far from 0 carry the rounding of degrees times pi/180).
TEST(SceneFile, SinAndCosOfDegreesAreExactAtRightAnglesAndCloseElsewhere) {
  for (const double right : {-720.0, -270.0, -180.0, -90.0, 0.0, 90.0, 180.0, 270.0, 360.0, 450.0}) {
    const auto [s, c] = sin_cos_degrees(right);
    const int quarter = ((int(right) / 90) % 4 + 4) % 4;
    EXPECT_EQ(s, (quarter == 1) - (quarter == 3)) << right;
    EXPECT_EQ(c, (quarter == 0) - (quarter == 2)) << right;
  }
  for (double degrees = -725; degrees < 725; degrees += 0.37) {
    const auto [s, c] = sin_cos_degrees(degrees);
    const double radians = std::remainder(degrees, 360.0) * std::numbers::pi / 180;
    EXPECT_NEAR(s, std::sin(radians), 1e-15) << degrees;
    EXPECT_NEAR(c, std::cos(radians), 1e-15) << degrees;
  }
}

// A plane is the points x with normal·x = offset, whatever the normal's length.
TEST(SceneFile, APlaneHoldsNormalDotXEqualsOffsetForAnyLength) {
  const Scene scene = scene_of("[[body]]\nshape = \"plane\"\nnormal = [0, 5, 0]\noffset = 1\n");
  const physics::Shape& plane = scene.bodies[0].shape;
  EXPECT_EQ(plane.normal, physics::Vec3::UnitY());
  EXPECT_DOUBLE_EQ(plane.offset, 0.2);
  const std::string error = error_of("[[body]]\nshape = \"plane\"\n\nnormal = [0, 0, 0]\n");
  EXPECT_NE(error.find(":4: [[body]] 'body 1' field 'normal': must not be the zero vector"), std::string::npos) << error;
}

// A ball or hinge joint to the world holds its body at the body's centre unless `anchor` says
// where; a rod or rope to the world must say where its fixed end is.
TEST(SceneFile, AJointToTheWorldAnchorsAtTheBodyOrWhereItSays) {
  const std::string ball = "[[body]]\nname = \"ball\"\nshape = \"sphere\"\nposition = [1, 2, 3]\n";
  const Scene pinned = scene_of(ball + "[[joint]]\ntype = \"ball\"\nb = \"ball\"\n");
  EXPECT_EQ(pinned.joints[0].anchor, physics::Vec3(1, 2, 3));
  const Scene hinged = scene_of(ball + "[[joint]]\ntype = \"hinge\"\na = \"ball\"\nanchor = [0, 2, 0]\n");
  EXPECT_EQ(hinged.joints[0].anchor, physics::Vec3(0, 2, 0));
  const Scene rod = scene_of(ball + "[[joint]]\ntype = \"rod\"\nb = \"ball\"\nanchor_a = [1, 4, 3]\n");
  EXPECT_EQ(rod.joints[0].anchor_a, physics::Vec3(1, 4, 3));
  EXPECT_EQ(rod.joints[0].anchor_b, physics::Vec3(1, 2, 3));
  const std::string error = error_of(ball + "[[joint]]\ntype = \"rope\"\nb = \"ball\"\n");
  EXPECT_NE(error.find(":5: [[joint]] 'joint 1' field 'anchor_a': missing: the fixed point the rope hangs from"),
            std::string::npos) << error;
}

// Every kind of check has a bound it can fail: a kind whose bound has no default refuses a check
// without one, and no kind takes another kind's bound.
TEST(SceneFile, ACheckThatCannotFailIsRefused) {
  const std::string ball = "[[body]]\nname = \"ball\"\nshape = \"sphere\"\n";
  for (const char* kind : {"inside", "velocity", "height"}) {
    const std::string error = error_of(ball + "[[check]]\nkind = \"" + kind + "\"\nbody = \"ball\"\n");
    EXPECT_NE(error.find(":4: [[check]] 1 field 'min': missing: "), std::string::npos) << error;
    EXPECT_NE(error.find("else it cannot fail"), std::string::npos) << error;
  }
  // The kinds with a default bound load, each with it.
  for (const char* kind : {"momentum", "energy", "penetration"})
    EXPECT_EQ(scene_of(ball + "[[check]]\nkind = \"" + kind + "\"\n").checks.size(), 1u) << kind;
  for (const char* kind : {"at_rest", "drift"})
    EXPECT_EQ(scene_of(ball + "[[check]]\nkind = \"" + kind + "\"\nbody = \"ball\"\n").checks.size(), 1u) << kind;
  EXPECT_NE(error_of(ball + "[[check]]\nkind = \"inside\"\nbody = \"ball\"\nmax = [1, 1, 1]\nspeed = 2\n")
                .find(":8: [[check]] 1 field 'speed': a check of kind \"inside\" does not use it (its bounds: `min`, `max`)"),
            std::string::npos);
  EXPECT_NE(error_of(ball + "[[check]]\nkind = \"height\"\nbody = \"ball\"\nmax = 1\ntolerance = 0.1\n")
                .find("field 'tolerance': bounds `ratio` only"),
            std::string::npos);
  EXPECT_NE(error_of(ball + "[[check]]\nkind = \"energy\"\nbody = \"ball\"\n").find("field 'body': a check of kind \"energy\" is about every body"),
            std::string::npos);
}

// --set takes one value: what follows it on a second line, or after it on the line, is refused.
TEST(SceneFile, ASetValueFollowedByAnythingIsRefused) {
  const std::string ball = "[[body]]\nname = \"ball\"\nshape = \"sphere\"\n";
  for (const std::string setting : {"body[ball].mass=1\nrestitution=5", "body[ball].mass=1 kg", "body[ball].mass=[1] 2",
                                    "body[ball].mass=1\n", "body[ball].mass=true x"}) {
    try {
      scene_of(ball, {setting});
      ADD_FAILURE() << setting << ": accepted";
    } catch (const SceneError& error) {
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
      EXPECT_EQ(std::string(error.what()).rfind("--set body[ball].mass=", 0), 0u) << error.what();
    }
  }
  EXPECT_EQ(scene_of(ball, {"body[ball].mass=1.5"}).bodies[0].mass, 1.5);
  EXPECT_EQ(scene_of(ball, {"body[ball].name=big ball"}).bodies[0].name, "big ball");  // a bare word
}


// [[material_pair]]: the pair's own friction and restitution reach the world's contacts; a value
// the pair leaves out, and any other pair, are mixed (the larger e, the geometric mean of mu).
TEST(SceneFile, MaterialPairsGiveTheirPairsTheirOwnFrictionAndRestitution) {
  const std::string path = write_scene("material_pairs", R"(
[[body]]
name = "cue"
shape = "sphere"
material = "ball"
friction = 0.05
restitution = 0.9
[[body]]
name = "red"
shape = "sphere"
position = [2, 0, 0]
material = "ball"
friction = 0.05
restitution = 0.9
[[body]]
name = "table"
shape = "plane"
material = "cloth"
friction = 0.8
restitution = 0.1
[[body]]
name = "wall"
shape = "plane"
normal = [1, 0, 0]
offset = -5
friction = 0.2
[[material_pair]]
between = ["cloth", "ball"]
friction = 0.2
[[material_pair]]
between = ["ball", "ball"]
restitution = 0.95
)");
  const Scene scene = load_scene(path);
  ASSERT_EQ(scene.material_names, (std::vector<std::string>{"ball", "cloth"}));
  const physics::World world = build_world(scene);
  const physics::ContactMaterial on_cloth = world.contact_material(0, 2);
  EXPECT_DOUBLE_EQ(on_cloth.friction, 0.2);      // the pair's, in either order
  EXPECT_DOUBLE_EQ(on_cloth.restitution, 0.9);   // left out: the larger of 0.9 and 0.1
  const physics::ContactMaterial on_ball = world.contact_material(1, 0);
  EXPECT_DOUBLE_EQ(on_ball.restitution, 0.95);
  EXPECT_DOUBLE_EQ(on_ball.friction, 0.05);      // sqrt(0.05 * 0.05)
  const physics::ContactMaterial on_wall = world.contact_material(0, 3);
  EXPECT_NEAR(on_wall.friction, std::sqrt(0.05 * 0.2), 1e-15);  // no pair: mixed
  EXPECT_DOUBLE_EQ(on_wall.restitution, 0.9);
}

// [world] planar locks every moving body (a pattern's too) unless the body's own planar says
// otherwise; a plane that is not one is refused at its line, with the planes there are.
TEST(SceneFile, PlanarLocksEveryMovingBodyUnlessItsOwnSaysOtherwise) {
  const Scene scene = scene_of(
      "[world]\nplanar = \"xy\"\n"
      "[[body]]\nname = \"ball\"\nshape = \"sphere\"\n"
      "[[body]]\nname = \"free\"\nshape = \"sphere\"\nposition = [2, 0, 0]\nplanar = \"none\"\n"
      "[[body]]\nname = \"side\"\nshape = \"sphere\"\nposition = [4, 0, 0]\nplanar = \"yz\"\n"
      "[[lattice]]\ncount = [2, 1, 1]\nposition = [0, 5, 0]\n");
  ASSERT_EQ(scene.bodies.size(), 5u);
  EXPECT_EQ(scene.bodies[0].planar_axis, 2);
  EXPECT_EQ(scene.bodies[1].planar_axis, physics::kNotPlanar);
  EXPECT_EQ(scene.bodies[2].planar_axis, 0);
  EXPECT_EQ(scene.bodies[3].planar_axis, 2);
  EXPECT_EQ(scene.bodies[4].planar_axis, 2);
  EXPECT_EQ(scene_of("[[body]]\nshape = \"sphere\"\n").bodies[0].planar_axis, physics::kNotPlanar);
  const std::string error = error_of("[world]\n\nplanar = \"x-y\"\n[[body]]\nshape = \"sphere\"\n");
  EXPECT_NE(error.find(":3: [world] field 'planar': unknown value 'x-y'"), std::string::npos) << error;
  EXPECT_NE(error.find("(known: yz, xz, xy, none)"), std::string::npos) << error;
}

// A lattice's bodies are named from 1 by its name; `position` is the middle of its bottom layer's
// centres, `size` a sphere's diameter; `static` makes every body static; a staggered layer of a
// lattice one body deep shifts along x alone, so it stays in its plane.
TEST(SceneFile, ALatticeIsNamedFromOneAroundTheMiddleOfItsBottomLayerAndMayBeStatic) {
  const Scene scene = scene_of(
      "[[body]]\nname = \"ground\"\nshape = \"plane\"\n"
      "[[lattice]]\nname = \"peg\"\nshape = \"sphere\"\nstatic = true\ncount = [3, 2, 1]\npitch = [0.2, 0.3, 1]\n"
      "position = [1, 2, 0]\nsize = 0.05\nstagger = true\n"
      "[[lattice]]\ncount = [1, 2, 1]\nposition = [5, 1, 0]\n");
  ASSERT_EQ(scene.bodies.size(), 9u);
  const double x[] = {0.8, 1.0, 1.2, 0.9, 1.1, 1.3};
  for (int i = 0; i < 6; ++i) {
    const physics::BodyDef& peg = scene.bodies[size_t(i) + 1];
    EXPECT_EQ(peg.name, "peg " + std::to_string(i + 1));
    EXPECT_TRUE(peg.is_static);
    EXPECT_EQ(peg.shape.type, physics::ShapeType::sphere);
    EXPECT_DOUBLE_EQ(peg.shape.radius, 0.025);
    EXPECT_NEAR(peg.position.x(), x[i], 1e-12) << peg.name;
    EXPECT_NEAR(peg.position.y(), i < 3 ? 2.0 : 2.3, 1e-12) << peg.name;
    EXPECT_EQ(peg.position.z(), 0) << peg.name;
  }
  EXPECT_EQ(scene.bodies[7].name, "lattice 2 1");
  EXPECT_EQ(scene.bodies[8].name, "lattice 2 2");
  EXPECT_FALSE(scene.bodies[8].is_static);
  EXPECT_EQ(scene.bodies[8].position, physics::Vec3(5, 3, 0));
  EXPECT_EQ(scene_of("[[lattice]]\ncount = [1, 1, 1]\n").bodies[0].name, "lattice 1");
}

// A hull's points are about `position` in the body's frame turned by `rotation`: the body sits at
// their hull's centre of mass, turned into its principal axes, and the corners land where the file
// put them. A right wedge's centroid is a third of each leg from its right angle.
TEST(SceneFile, AHullsBodyIsAtItsCentreOfMassAndItsCornersWhereTheFilePutThem) {
  const Scene scene = load_scene(write_scene("hull", R"([[body]]
name = "wedge"
shape = "wedge"
size = [0.9, 0.3, 0.5]
position = [1, 2, 3]
rotation = [0, 90, 0]

[[body]]
name = "die"
shape = "hull"
points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.2, 0.2, 0.2]]
inertia = "hollow"
)"));
  ASSERT_EQ(scene.bodies.size(), 2u);
  const physics::BodyDef& wedge = scene.bodies[0];
  ASSERT_EQ(wedge.shape.type, physics::ShapeType::hull);
  const physics::Quat turn = rotation_from_degrees(physics::Vec3(0, 90, 0));
  EXPECT_LT((wedge.position - (physics::Vec3(1, 2, 3) + physics::rotate(turn, physics::Vec3(-0.15, -0.05, 0)))).norm(), 1e-12);
  EXPECT_NEAR(physics::shape_volume(wedge.shape), 0.9 * 0.3 * 0.5 / 2, 1e-12);
  for (const physics::Vec3& corner : wedge.shape.hull()->corners) {
    const physics::Vec3 in_file = physics::rotate(turn.conjugate(), wedge.position + physics::rotate(wedge.orientation, corner) - physics::Vec3(1, 2, 3));
    EXPECT_NEAR(std::abs(in_file.x()), 0.45, 1e-12);
    EXPECT_NEAR(std::abs(in_file.y()), 0.15, 1e-12);
    EXPECT_NEAR(std::abs(in_file.z()), 0.25, 1e-12);
  }
  // The corner of the unit tetrahedron and the point inside it: four corners, and, hollow, the body at
  // the surface's centre: three right triangles of area 1/2 (centres at thirds) and one of area
  // sqrt(3)/2 (its centre at (1/3, 1/3, 1/3)).
  const physics::BodyDef& die = scene.bodies[1];
  EXPECT_EQ(die.shape.hull()->corners.size(), 4u);
  const double right = 0.5, slanted = std::sqrt(3.0) / 2;
  const double each = (2 * right * (1.0 / 3) + slanted * (1.0 / 3)) / (3 * right + slanted);
  EXPECT_LT((die.position - physics::Vec3::Constant(each)).norm(), 1e-12);
}

// A mesh's file is read from the scene's folder, scaled, and placed by position and rotation;
// the body is static whatever the file says of it, and `static = false` is refused.
TEST(SceneFile, AMeshIsItsFilesTrianglesFromTheScenesFolderPlacedAndStatic) {
  const std::filesystem::path obj = std::filesystem::path(write_scene("mesh", "")).parent_path() / "impulse_scene_test_ramp.obj";
  std::ofstream(obj) << "v 0 0 0\nv 0 0 -1\nv 1 0 0\nv 1 1 -1\nf 1 3 2\nf 2 3 4\n";
  const Scene scene = load_scene(write_scene("mesh", R"([[body]]
name = "ramp"
shape = "mesh"
file = "impulse_scene_test_ramp.obj"
scale = 2
position = [1, 0, 0]
rotation = [0, 90, 0]
)"));
  ASSERT_EQ(scene.bodies.size(), 1u);
  const physics::BodyDef& ramp = scene.bodies[0];
  ASSERT_EQ(ramp.shape.type, physics::ShapeType::mesh);
  EXPECT_TRUE(ramp.is_static);
  ASSERT_EQ(ramp.shape.mesh()->triangles.size(), 2u);
  EXPECT_TRUE(ramp.shape.mesh()->vertices[3].isApprox(physics::Vec3(2, 2, -2)));
  EXPECT_LT((ramp.position - physics::Vec3(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((physics::rotate(ramp.orientation, physics::Vec3::UnitX()) - physics::Vec3(0, 0, -1)).norm(), 1e-12);
  try {
    load_scene(write_scene("mesh_moving", "[[body]]\nshape = \"mesh\"\nfile = \"impulse_scene_test_ramp.obj\"\nstatic = false\n"));
    FAIL() << "a moving mesh was taken";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("field 'static': a mesh is always static"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace impulse::demos
