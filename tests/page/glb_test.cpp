// `impulse export --format glb`: a scene's run as glTF 2.0 binary. The Khronos validator finds no
// error or warning in it; read back with tinygltf, it holds a node per body with the body's name,
// colour and size, and its animation puts each body where the trace of the same run puts it.
// With --marks, a node "marks" holds the video's arrows: at every frame those shown are the frame's
// draw list's, the other slots at scale 0.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "demos/film/marks.h"
#include "demos/film/render_types.h"
#include "demos/film/scene_draw_list.h"
#include "demos/film/world_take.h"
#include "demos/scene/scene_file.h"
#include "tests/support/child_process.h"
#include "tests/support/traced_poses.h"
#include "tests/support/scene_scratch.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

using testing::Pose;
using testing::Poses;

// The validator's counts and messages (tests/page/validate_glb.mjs).
struct Report {
  int errors = -1, warnings = -1, infos = -1, hints = -1;
  std::string text;
};
Report validated(const fs::path& glb, const fs::path& dir) {
  const fs::path out = dir / "report.txt";
  const testing::ChildResult node = testing::run_child(
      {"/bin/sh", "-c",
       "timeout 120 node '" IMPULSE_SOURCE_DIR "/tests/page/validate_glb.mjs' '" + glb.string() + "' > '" + out.string() + "'"});
  EXPECT_TRUE(node.succeeded()) << node.describe();
  Report report;
  report.text = contents(out);
  std::istringstream words(report.text);
  std::string word;
  words >> word >> report.errors >> word >> report.warnings >> word >> report.infos >> word >> report.hints;
  return report;
}

// An accessor's floats, `width` per element.
std::vector<float> floats(const tinygltf::Model& model, int index, int width) {
  const tinygltf::Accessor& accessor = model.accessors.at(size_t(index));
  EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(tinygltf::GetNumComponentsInType(uint32_t(accessor.type)), width);
  const tinygltf::BufferView& view = model.bufferViews.at(size_t(accessor.bufferView));
  const std::vector<unsigned char>& data = model.buffers.at(size_t(view.buffer)).data;
  const size_t stride = size_t(accessor.ByteStride(view));
  std::vector<float> values(accessor.count * size_t(width));
  for (size_t e = 0; e < accessor.count; ++e) {
    const size_t at = view.byteOffset + accessor.byteOffset + e * stride;
    EXPECT_LE(at + size_t(width) * 4, data.size());
    if (at + size_t(width) * 4 > data.size()) return {};
    std::memcpy(&values[e * size_t(width)], &data[at], size_t(width) * 4);
  }
  return values;
}

double linear(double srgb) { return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4); }

// What one scene's glb holds, against the scene and the trace of the same run.
void check_glb(const std::string& source, const fs::path& glb, const fs::path& dir, const std::string& name, bool marks = false) {
  const demos::Scene scene = demos::load_scene(source);
  ASSERT_EQ(contents(glb).substr(0, 4), "glTF");

  // The validator: no error, no warning.
  const Report report = validated(glb, dir);
  EXPECT_EQ(report.errors, 0) << report.text;
  EXPECT_EQ(report.warnings, 0) << report.text;
  ::testing::Test::RecordProperty("validator", report.text.substr(0, report.text.find('\n')));

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, glb.string())) << error << warning;
  ASSERT_EQ(model.scenes.size(), 1u);

  // A node per body, by name, with its mesh; the camera; the rods in "joints".
  std::map<std::string, int> node_of;
  int camera_node = -1, joints_node = -1, marks_node = -1;
  for (const int n : model.scenes[0].nodes) {
    const tinygltf::Node& node = model.nodes.at(size_t(n));
    if (node.camera >= 0) camera_node = n;
    else if (node.mesh >= 0) node_of[node.name] = n;
    else if (node.name == "joints") joints_node = n;
    else if (node.name == "marks") marks_node = n;
    else ADD_FAILURE() << "a node neither body, camera, joints nor marks: " << node.name;
  }
  EXPECT_EQ(marks_node >= 0, marks) << name << ": a node \"marks\" with --marks only";
  ASSERT_EQ(node_of.size(), scene.bodies.size()) << "a node per body, each by its own name";
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const physics::BodyDef& body = scene.bodies[i];
    ASSERT_TRUE(node_of.contains(body.name)) << body.name;
    const tinygltf::Node& node = model.nodes[size_t(node_of[body.name])];
    ASSERT_GE(node.mesh, 0) << body.name;
    const tinygltf::Primitive& primitive = model.meshes.at(size_t(node.mesh)).primitives.at(0);

    // Its colour, linear; the ground the video's light grey.
    const bool ground = body.shape.type == physics::ShapeType::plane && body.shape.normal.normalized().y() > 0.999;
    const demos::Colour srgb = ground ? demos::Colour{0.84f, 0.85f, 0.86f} : scene.colours[i];
    const std::vector<double>& factor = model.materials.at(size_t(primitive.material)).pbrMetallicRoughness.baseColorFactor;
    ASSERT_EQ(factor.size(), 4u);
    EXPECT_NEAR(factor[0], linear(srgb.r), 1e-3) << body.name;
    EXPECT_NEAR(factor[1], linear(srgb.g), 1e-3) << body.name;
    EXPECT_NEAR(factor[2], linear(srgb.b), 1e-3) << body.name;

    // Its size: a box's mesh spans twice its half extents; a plane's lies in the plane.
    const std::vector<float> corners = floats(model, primitive.attributes.at("POSITION"), 3);
    if (body.shape.type == physics::ShapeType::box) {
      for (int k = 0; k < 3; ++k) {
        float low = HUGE_VALF, high = -HUGE_VALF;
        for (size_t v = size_t(k); v < corners.size(); v += 3) low = std::min(low, corners[v]), high = std::max(high, corners[v]);
        EXPECT_NEAR(high - low, 2 * body.shape.half_extents[k], 1e-5) << body.name << " along axis " << k;
      }
    }
    if (body.shape.type == physics::ShapeType::plane) {
      const Eigen::Vector3d n = body.shape.normal.normalized();
      for (size_t v = 0; v + 2 < corners.size(); v += 3)
        EXPECT_NEAR(n.dot(Eigen::Vector3d(corners[v], corners[v + 1], corners[v + 2])), body.shape.offset, 1e-4) << body.name;
    }
  }

  // The camera: at the scene's, looking down its -z at the scene's target.
  ASSERT_GE(camera_node, 0) << "a camera node";
  {
    const tinygltf::Node& node = model.nodes[size_t(camera_node)];
    ASSERT_EQ(node.translation.size(), 3u);
    ASSERT_EQ(node.rotation.size(), 4u);
    const Eigen::Vector3d eye(node.translation[0], node.translation[1], node.translation[2]);
    EXPECT_NEAR((eye - scene.camera.position.cast<double>()).norm(), 0, 1e-5);
    const Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const Eigen::Vector3d ahead = (scene.camera.target - scene.camera.position).cast<double>().normalized();
    EXPECT_NEAR((q * Eigen::Vector3d(0, 0, -1) - ahead).norm(), 0, 1e-5);
    EXPECT_NEAR(model.cameras.at(size_t(node.camera)).perspective.yfov, scene.camera.fov_y_degrees * M_PI / 180, 1e-6);
  }

  // The animation: a key at every video frame; at a third and two thirds of the run (frames that
  // are also steps of the trace) each body where the trace puts it.
  const int fps = scene.video.fps;
  const long frames = std::max(1L, std::lround(std::ceil(scene.duration * fps - 0.5)));
  std::map<std::pair<int, std::string>, const tinygltf::AnimationSampler*> channel;  // (node, path)
  ASSERT_LE(model.animations.size(), 1u);
  for (const tinygltf::Animation& animation : model.animations) {
    EXPECT_EQ(animation.name, "run");
    for (const tinygltf::AnimationChannel& c : animation.channels) channel[{c.target_node, c.target_path}] = &animation.samplers.at(size_t(c.sampler));
  }
  auto at_frame = [&](int node, const std::string& path, long frame, int width) -> std::vector<double> {
    const auto found = channel.find({node, path});
    if (found == channel.end()) {  // not animated: where the node stands
      const std::vector<double>& still = path == "translation" ? model.nodes[size_t(node)].translation : model.nodes[size_t(node)].rotation;
      if (!still.empty()) return still;
      return path == "translation" ? std::vector<double>{0, 0, 0} : std::vector<double>{0, 0, 0, 1};
    }
    EXPECT_EQ(found->second->interpolation, "LINEAR");
    const std::vector<float> times = floats(model, found->second->input, 1), values = floats(model, found->second->output, width);
    EXPECT_EQ(long(times.size()), frames) << "a key per video frame";
    EXPECT_EQ(values.size(), times.size() * size_t(width));
    for (size_t k = 0; k < times.size(); ++k)
      if (std::abs(times[k] - double(frame) / fps) < 1e-5 && (k + 1) * size_t(width) <= values.size())
        return std::vector<double>(values.begin() + long(k) * width, values.begin() + long(k + 1) * width);
    ADD_FAILURE() << "no key at frame " << frame;
    return std::vector<double>(size_t(width), 0.0);
  };
  // A rod's ends: its node's unit rod along y, moved, turned and stretched.
  auto rod_ends = [&](int node, long frame) {
    const std::vector<double> at = at_frame(node, "translation", frame, 3), turn = at_frame(node, "rotation", frame, 4),
                              scale = at_frame(node, "scale", frame, 3);
    const Eigen::Vector3d middle(at[0], at[1], at[2]);
    const Eigen::Vector3d half = Eigen::Quaterniond(turn[3], turn[0], turn[1], turn[2]).normalized() * Eigen::Vector3d(0, scale[1] / 2, 0);
    return std::pair{Eigen::Vector3d(middle - half), Eigen::Vector3d(middle + half)};
  };
  std::vector<long> moments_ms, moment_frames;
  for (const int share : {1, 2}) {
    const long frame = std::lround(scene.duration * share / 3 * fps);
    moment_frames.push_back(frame);
    moments_ms.push_back(std::lround(1000.0 * frame / fps));
  }
  const fs::path trace = dir / "trace.csv";
  const testing::ChildResult simulated = testing::run_child({IMPULSE_PROGRAM, "-q", "simulate", source, "--trace", trace.string()});
  ASSERT_TRUE(simulated.succeeded()) << simulated.describe();
  const Poses expected = testing::traced_poses(trace, moments_ms);
  int compared = 0;
  for (const auto& [key, pose] : expected) {
    const auto named = node_of.find(key.first);
    ASSERT_NE(named, node_of.end()) << key.first;
    const int i = demos::find_body(scene, key.first);
    if (i >= 0 && scene.bodies[size_t(i)].shape.type == physics::ShapeType::plane) continue;  // in the world's frame
    const long frame = moment_frames[key.second == moments_ms[0] ? 0 : 1];
    const std::vector<double> at = at_frame(named->second, "translation", frame, 3), turn = at_frame(named->second, "rotation", frame, 4);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(at[size_t(k)], pose[size_t(k)], 1e-4) << name << ": " << key.first << " at " << key.second << " ms";
    // glTF's x y z w against the trace's w x y z, either sign.
    const double dot = turn[3] * pose[3] + turn[0] * pose[4] + turn[1] * pose[5] + turn[2] * pose[6];
    EXPECT_NEAR(std::abs(dot), 1, 1e-4) << name << ": " << key.first << " at " << key.second << " ms: its orientation";
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(std::abs(turn[size_t(k)]), std::abs(pose[size_t(3 + (k + 1) % 4)]), 1e-4) << name << ": " << key.first << " at " << key.second << " ms";
    ++compared;
  }
  EXPECT_GE(compared, 1) << "bodies compared: the moments are no steps of the trace";

  // Each rod or rope from anchor to anchor: a world anchor where the scene puts it, a body's as far
  // from the body's traced centre as the scene puts it from the body's first.
  std::map<std::string, int> rod_of;
  if (joints_node >= 0)
    for (const int child : model.nodes[size_t(joints_node)].children) rod_of[model.nodes.at(size_t(child)).name] = child;
  size_t rods = 0;
  for (const physics::JointDef& joint : scene.joints) {
    if (joint.type != physics::JointType::distance) continue;
    ++rods;
    ASSERT_TRUE(rod_of.contains(joint.name)) << name << ": " << joint.name;
    for (size_t m = 0; m < moments_ms.size(); ++m) {
      const auto [end_a, end_b] = rod_ends(rod_of[joint.name], moment_frames[m]);
      for (const auto& [body, anchor, end] : {std::tuple{joint.body_a, joint.anchor_a, end_a}, std::tuple{joint.body_b, joint.anchor_b, end_b}}) {
        if (body == physics::kWorld) {
          EXPECT_NEAR((end - anchor).norm(), 0, 1e-4) << name << ": " << joint.name << " at " << moments_ms[m] << " ms";
          continue;
        }
        const physics::BodyDef& def = scene.bodies[size_t(body)];
        const auto traced_pose = expected.find({def.name, moments_ms[m]});
        if (traced_pose == expected.end()) continue;
        const Eigen::Vector3d centre(traced_pose->second[0], traced_pose->second[1], traced_pose->second[2]);
        EXPECT_NEAR((end - centre).norm(), (anchor - def.position).norm(), 1e-4) << name << ": " << joint.name << " at " << moments_ms[m] << " ms";
      }
    }
  }
  EXPECT_EQ(rod_of.size(), rods) << name << ": a rod per rod or rope joint";
}

// The arrows of each video frame as the video (and the page) draws them: the draw list at the
// scene's camera, with the run's arrow scales.
std::vector<std::vector<render::ArrowItem>> drawn_arrows(const demos::Scene& scene) {
  demos::WorldTake take(scene);
  const int fps = scene.video.fps;
  const long frames = std::max(1L, std::lround(std::ceil(scene.duration * fps - 0.5)));
  std::vector<demos::FrameSample> samples(static_cast<size_t>(frames));
  for (long k = 0; k < frames; ++k) {
    const double time = double(k) / fps;
    while (!take.finished() && take.time() < time - 1e-9) take.step();
    take.sample(time, time, samples[size_t(k)]);
  }
  const demos::ArrowScales scales = demos::arrow_scales(scene, take.summary());
  std::vector<physics::Body> bodies = take.bodies();
  std::vector<std::vector<render::ArrowItem>> arrows;
  for (const demos::FrameSample& sample : samples) {
    for (size_t i = 0; i < bodies.size(); ++i) bodies[i].velocity = sample.velocities[i];
    arrows.push_back(demos::scene_draw_list(scene, bodies, sample.poses, take.joints(), sample.contacts, scales,
                                            demos::to_render(scene.camera)).arrows);
  }
  return arrows;
}

// The glb's arrows against the draw lists, at every frame: the slots shown (scale not 0) are the
// frame's arrows, origin and tip to 1e-4 m, colour (linear) to 1e-3; the others at scale 0.
// Returns the arrows compared.
size_t check_marks(const demos::Scene& scene, const tinygltf::Model& model, const std::string& name) {
  const std::vector<std::vector<render::ArrowItem>> expected = drawn_arrows(scene);
  int marks = -1;
  for (const int n : model.scenes.at(0).nodes)
    if (model.nodes.at(size_t(n)).name == "marks") marks = n;
  if (marks < 0) {
    ADD_FAILURE() << name << ": no node \"marks\"";
    return 0;
  }
  std::map<std::pair<int, std::string>, const tinygltf::AnimationSampler*> channel;
  for (const tinygltf::Animation& animation : model.animations)
    for (const tinygltf::AnimationChannel& c : animation.channels) channel[{c.target_node, c.target_path}] = &animation.samplers.at(size_t(c.sampler));
  // Each slot: its colour and its keys (translation, rotation, scale) per frame.
  struct Slot {
    std::string name;
    std::vector<double> colour;
    std::vector<float> at, turn, scale;
  };
  std::vector<Slot> slots;
  const long frames = long(expected.size());
  for (const int kind : model.nodes[size_t(marks)].children)
    for (const int n : model.nodes.at(size_t(kind)).children) {
      const tinygltf::Node& node = model.nodes.at(size_t(n));
      Slot slot{node.name, {}, {}, {}, {}};
      EXPECT_EQ(slot.name.rfind(model.nodes[size_t(kind)].name + " ", 0), 0u) << slot.name << " under " << model.nodes[size_t(kind)].name;
      EXPECT_GE(node.mesh, 0) << slot.name;
      if (node.mesh < 0) continue;
      const tinygltf::Material& material = model.materials.at(size_t(model.meshes.at(size_t(node.mesh)).primitives.at(0).material));
      EXPECT_TRUE(material.extensions.contains("KHR_materials_unlit")) << slot.name;
      slot.colour = material.pbrMetallicRoughness.baseColorFactor;
      for (const auto& [path, width, keys] : {std::tuple{"translation", 3, &slot.at}, std::tuple{"rotation", 4, &slot.turn}, std::tuple{"scale", 3, &slot.scale}}) {
        const auto found = channel.find({n, path});
        if (found == channel.end()) {
          ADD_FAILURE() << name << ": " << slot.name << " has no " << path;
          return 0;
        }
        EXPECT_EQ(found->second->interpolation, "STEP") << slot.name;
        const std::vector<float> times = floats(model, found->second->input, 1);
        EXPECT_EQ(long(times.size()), frames) << slot.name << ": a key per video frame";
        for (size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(times[k], double(k) / scene.video.fps, 1e-5);
        *keys = floats(model, found->second->output, width);
        if (long(keys->size()) != frames * width) {
          ADD_FAILURE() << name << ": " << slot.name << "'s " << path << " keys";
          return 0;
        }
      }
      slots.push_back(std::move(slot));
    }
  size_t compared = 0;
  for (long k = 0; k < frames; ++k) {
    std::vector<bool> matched(slots.size());
    size_t shown = 0;
    for (const Slot& slot : slots) {
      const float* scale = &slot.scale[size_t(k) * 3];
      if (scale[1] != 0) ++shown;
      else EXPECT_TRUE(scale[0] == 0 && scale[2] == 0) << name << ": " << slot.name << " at frame " << k << ": an empty slot at scale 0";
    }
    EXPECT_EQ(shown, expected[size_t(k)].size()) << name << ": frame " << k << "'s arrows";
    for (const render::ArrowItem& arrow : expected[size_t(k)]) {
      const Eigen::Vector3d origin = arrow.origin.cast<double>(), tip = (arrow.origin + arrow.direction).cast<double>();
      const Eigen::Vector3d colour(linear(arrow.colour.r), linear(arrow.colour.g), linear(arrow.colour.b));
      bool found = false;
      for (size_t s = 0; s < slots.size() && !found; ++s) {
        const Slot& slot = slots[s];
        const float *at = &slot.at[size_t(k) * 3], *turn = &slot.turn[size_t(k) * 4], *scale = &slot.scale[size_t(k) * 3];
        if (matched[s] || scale[1] == 0 || (Eigen::Vector3d(slot.colour[0], slot.colour[1], slot.colour[2]) - colour).norm() > 1e-3) continue;
        const Eigen::Vector3d from(at[0], at[1], at[2]);
        const Eigen::Vector3d to = from + Eigen::Quaterniond(turn[3], turn[0], turn[1], turn[2]).normalized() * Eigen::Vector3d(0, scale[1], 0);
        if ((from - origin).norm() < 1e-4 && (to - tip).norm() < 1e-4) found = matched[s] = true;
      }
      EXPECT_TRUE(found) << name << ": frame " << k << ": no slot shows the arrow from " << origin.transpose() << " to " << tip.transpose();
      compared += found;
    }
  }
  return compared;
}

// --marks: the glb validates and holds the video's arrows (bounce: impulses, friction and
// velocities; s5_boxes: contact normals and impulses), each frame's as its draw list; without it
// no node "marks".
TEST(Glb, MarksHoldTheVideosArrowsAtEveryFrame) {
  for (const std::string name : {"bounce", "s5_boxes"}) {
    const fs::path dir = testing::scratch("glb_test", "marks_" + name);
    const std::string source = std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/" + name + ".toml";
    const fs::path glb = dir / (name + ".glb");
    const testing::ChildResult exported =
        testing::run_child({IMPULSE_PROGRAM, "-q", "export", source, "--format", "glb", "--marks", "-o", glb.string()});
    ASSERT_TRUE(exported.succeeded()) << exported.describe();
    check_glb(source, glb, dir, name, true);

    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, glb.string())) << error << warning;
    const size_t compared = check_marks(demos::load_scene(source), model, name);
    EXPECT_GE(compared, 100u) << name << ": arrows compared";
    ::testing::Test::RecordProperty(name + "_arrows", int(compared));
  }
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

// Each catalogue scene, exported to NAME.glb (the format from -o's extension).
TEST_P(EveryScene, TheGlbValidatesAndPutsEachBodyWhereTheTraceDoes) {
  const std::string name = GetParam();
  const fs::path dir = testing::scratch("glb_test", name);
  const std::string source = std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/" + name + ".toml";
  const fs::path glb = dir / (name + ".glb");
  const testing::ChildResult exported = testing::run_child({IMPULSE_PROGRAM, "-q", "export", source, "-o", glb.string()});
  ASSERT_TRUE(exported.succeeded()) << exported.describe();
  check_glb(source, glb, dir, name);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, EveryScene, ::testing::ValuesIn(testing::catalogue_scene_names()),
                         [](const ::testing::TestParamInfo<std::string>& scene) { return scene.param; });

// --format glb without -o: out/NAME.glb under the working directory.
TEST(Glb, FormatGlbWritesOutNameGlb) {
  const fs::path dir = testing::scratch("glb_test", "default_path");
  const std::string source = std::string(IMPULSE_SOURCE_DIR) + "/assets/scenes/ex5_newtons_cradle.toml";
  testing::ChildSettings settings;
  settings.working_directory = dir.string();
  const testing::ChildResult exported = testing::run_child({IMPULSE_PROGRAM, "-q", "export", source, "--format", "glb"}, settings);
  ASSERT_TRUE(exported.succeeded()) << exported.describe();
  EXPECT_EQ(contents(dir / "out/ex5_newtons_cradle.glb").substr(0, 4), "glTF");
  EXPECT_FALSE(fs::exists(dir / "out/ex5_newtons_cradle.html"));
}

// A scene that cannot be read writes no glb, and says where it is wrong.
TEST(Glb, ABadSceneWritesNothing) {
  const fs::path dir = testing::scratch("glb_test", "bad");
  std::ofstream(dir / "bad.toml") << "[[body]]\nshape = \"mesh\"\nfile = \"nowhere.obj\"\n";
  const testing::ChildResult exported =
      testing::run_child({IMPULSE_PROGRAM, "-q", "export", (dir / "bad.toml").string(), "--format", "glb", "-o", (dir / "bad.glb").string()});
  EXPECT_EQ(exported.exit_code, 1) << exported.describe();
  EXPECT_NE(exported.stderr_text.find("bad.toml:3: [[body]] 'body 1' field 'file': no file"), std::string::npos) << exported.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "bad.glb"));
  for (const auto& entry : fs::directory_iterator(dir)) EXPECT_NE(entry.path().extension(), ".part") << entry.path();
}

}  // namespace
}  // namespace impulse
