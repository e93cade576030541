// Flat meshes (MeshItem, make_flat_mesh): a tetrahedron and a wedge drawn in their colour where
// they project, one shade a face and a different one for faces turned differently, their faces'
// sides outlined (not the diagonals that split a face into triangles), shadows on the ground by
// either method, the sleeping look, outlines anti-aliased as well as 4x multisampling.
// IMPULSE_MESH_TEST_PNG=DIR writes the frames looked at to DIR.
#include "render/antialias_reference.h"
#include "render/camera_view.h"
#include "render/mesh.h"
#include "render/png_io.h"
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace impulse {
namespace {

using render::Vec3f;
using Corners = std::shared_ptr<const std::vector<Vec3f>>;

constexpr int kWidth = 640;
constexpr int kHeight = 480;

// A polyhedron as its corners and its faces (corner indices, counter-clockwise seen from outside).
struct Polyhedron {
  std::vector<Vec3f> corners;
  std::vector<std::vector<int>> faces;

  Vec3f face_centre(size_t face) const {
    Vec3f sum = Vec3f::Zero();
    for (const int corner : faces[face]) sum += corners[size_t(corner)];
    return sum / float(faces[face].size());
  }
  Vec3f face_normal(size_t face) const {
    const std::vector<int>& f = faces[face];
    const Vec3f &a = corners[size_t(f[0])], &b = corners[size_t(f[1])], &c = corners[size_t(f[2])];
    return (b - a).cross(c - a).normalized();
  }
  // Each face fanned from its first corner, as the film does.
  Corners triangles() const {
    auto out = std::make_shared<std::vector<Vec3f>>();
    for (const std::vector<int>& face : faces)
      for (size_t k = 1; k + 1 < face.size(); ++k)
        for (const int corner : {face[0], face[k], face[k + 1]}) out->push_back(corners[size_t(corner)]);
    return out;
  }
};

// A regular tetrahedron of edge `edge`, one face down, about its centroid.
Polyhedron tetrahedron(float edge) {
  const float r = edge / std::sqrt(3.0f);               // the base's corners from its centre
  const float height = edge * std::sqrt(2.0f / 3.0f);
  Polyhedron p;
  for (int i = 0; i < 3; ++i) {
    const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / 3.0f;
    p.corners.emplace_back(r * std::cos(angle), -height / 4.0f, -r * std::sin(angle));
  }
  p.corners.emplace_back(0.0f, 0.75f * height, 0.0f);
  p.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  return p;
}

// A wedge of size x, y, z: the right triangle in x-y (its right angle at (-x/2, -y/2)) drawn along z;
// three of its five faces are rectangles (two triangles each).
Polyhedron wedge(const Vec3f& size) {
  const Vec3f h = size / 2.0f;
  Polyhedron p;
  p.corners = {{-h.x(), -h.y(), h.z()}, {h.x(), -h.y(), h.z()}, {-h.x(), h.y(), h.z()},
               {-h.x(), -h.y(), -h.z()}, {h.x(), -h.y(), -h.z()}, {-h.x(), h.y(), -h.z()}};
  p.faces = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {0, 2, 5, 3}, {1, 4, 5, 2}};
  return p;
}

const uint8_t* pixel(const render::Frame& frame, int x, int y) { return frame.rgba.data() + 4 * (size_t(y) * frame.width + x); }

int difference(const uint8_t* a, const uint8_t* b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}
int brightness(const uint8_t* p) { return int(p[0]) + int(p[1]) + int(p[2]); }

// The pixel where `world` lands (rounded down: the pixel holding that point).
const uint8_t* pixel_at(const render::Frame& frame, const render::DrawList& list, const Vec3f& world) {
  const auto at = render::make_camera_view(list.camera, frame.width, frame.height).to_pixels(world);
  EXPECT_TRUE(at.has_value());
  const int x = std::clamp(int(std::floor(at->x())), 0, frame.width - 1), y = std::clamp(int(std::floor(at->y())), 0, frame.height - 1);
  return pixel(frame, x, y);
}

bool is_red(const uint8_t* p) { return p[0] > p[1] + 60 && p[0] > p[2] + 60; }

void maybe_write(const render::Frame& frame, const std::string& name) {
  if (const char* dir = std::getenv("IMPULSE_MESH_TEST_PNG")) render::write_png(std::string(dir) + "/" + name + ".png", frame);
}

render::MeshItem red_mesh(const Corners& triangles, const Vec3f& centre, const render::Quatf& orientation = render::Quatf::Identity()) {
  render::MeshItem mesh;
  mesh.centre = centre;
  mesh.orientation = orientation;
  mesh.triangles = triangles;
  mesh.colour = {0.85f, 0.2f, 0.15f};
  return mesh;
}

// The tetrahedron and the wedge turned a little, side by side on the ground.
struct TwoSolids {
  Polyhedron tetra = tetrahedron(1.2f), block = wedge({1.2f, 0.8f, 0.9f});
  render::Quatf tetra_turn{Eigen::AngleAxisf(0.4f, Vec3f::UnitY())};
  render::Quatf wedge_turn{Eigen::AngleAxisf(-0.5f, Vec3f::UnitY())};
  Vec3f tetra_centre{-1.1f, 1.2f * std::sqrt(2.0f / 3.0f) / 4.0f, 0.0f};
  Vec3f wedge_centre{1.1f, 0.4f, 0.0f};
  render::DrawList list;

  TwoSolids() {
    list.camera.position = {0.5f, 2.2f, 5.0f};
    list.camera.target = {0.0f, 0.4f, 0.0f};
    list.meshes.push_back(red_mesh(tetra.triangles(), tetra_centre, tetra_turn));
    list.meshes.push_back(red_mesh(block.triangles(), wedge_centre, wedge_turn));
  }
  Vec3f tetra_world(const Vec3f& local) const { return tetra_centre + tetra_turn * local; }
  Vec3f wedge_world(const Vec3f& local) const { return wedge_centre + wedge_turn * local; }
  bool faces_camera(const Vec3f& world, const Vec3f& world_normal) const {
    return world_normal.dot(list.camera.position - world) > 0.0f;
  }
};

// Every triangle faces out with a unit normal of its own, the same at its three corners; a side's
// outline value is 0 along it where it bounds a face and 1 throughout where it is the diagonal that
// splits a rectangle; a triangle without area is left out.
TEST(Meshes, AFlatMeshHasOneNormalATriangleAndOutlinesOnlyTheFacesSides) {
  const Polyhedron block = wedge({1.2f, 0.8f, 0.9f});
  std::vector<Vec3f> corners = *block.triangles();
  corners.insert(corners.end(), {Vec3f::Zero(), Vec3f::UnitX(), 2.0f * Vec3f::UnitX()});  // no area
  const render::MeshData mesh = render::make_flat_mesh(corners);
  ASSERT_EQ(mesh.vertices.size(), 3u * 8u);  // two triangles and three rectangles of two
  ASSERT_EQ(mesh.indices.size(), mesh.vertices.size());
  Vec3f inside = Vec3f::Zero();  // its centroid (the slope's plane passes through its box's centre)
  for (const Vec3f& corner : block.corners) inside += corner / float(block.corners.size());
  int diagonals = 0;
  for (size_t t = 0; t < mesh.indices.size() / 3; ++t) {
    const render::MeshVertex* v[3] = {&mesh.vertices[mesh.indices[3 * t]], &mesh.vertices[mesh.indices[3 * t + 1]],
                                      &mesh.vertices[mesh.indices[3 * t + 2]]};
    auto position = [&](int k) { return Vec3f(v[k]->position[0], v[k]->position[1], v[k]->position[2]); };
    const Vec3f normal(v[0]->normal[0], v[0]->normal[1], v[0]->normal[2]);
    EXPECT_NEAR(normal.norm(), 1.0f, 1e-5f);
    EXPECT_GT(normal.dot(position(0) - inside), 0.0f) << "triangle " << t << " faces in";
    for (int k = 0; k < 3; ++k)
      for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(v[k]->normal[axis], v[0]->normal[axis]);
    for (int side = 0; side < 3; ++side) {  // the side across from corner `side`
      const bool outlines = v[(side + 1) % 3]->outline[side] == 0.0f;
      if (!outlines) ++diagonals;
      for (int k = 0; k < 3; ++k) EXPECT_EQ(v[k]->outline[side], outlines ? (k == side ? 1.0f : 0.0f) : 1.0f);
    }
  }
  EXPECT_EQ(diagonals, 2 * 3);  // each rectangle's diagonal, seen from both its triangles
}

// Two triangles sharing a side draw a line along it only where they meet at 5 degrees or more: a
// surface made of gently turned triangles (a half-pipe's strips) reads as one surface, a
// polyhedron's faces stay outlined.
TEST(Meshes, TrianglesMeetingWithinFiveDegreesDrawNoLineBetweenThem) {
  for (const float degrees : {0.0f, 1.25f, 4.5f, 5.5f, 22.5f}) {
    SCOPED_TRACE(degrees);
    const float turn = degrees * 3.14159265f / 180;
    // (0,0,0)-(0,0,1) is the shared side; the second triangle turns about it by `turn`.
    const std::vector<Vec3f> corners{{0, 0, 0}, {0, 0, 1}, {-1, 0, 0},
                                     {0, 0, 1}, {0, 0, 0}, {std::cos(turn), std::sin(turn), 0}};
    const render::MeshData mesh = render::make_flat_mesh(corners);
    ASSERT_EQ(mesh.vertices.size(), 6u);
    // The first triangle's side across from its corner 2 is the shared one.
    const bool outlined = mesh.vertices[mesh.indices[0]].outline[2] == 0.0f;
    EXPECT_EQ(outlined, degrees >= 5.0f);
  }
}

// Each face the camera sees is red where it projects, one shade across (sampled well inside it),
// and the faces turned differently to the light differ; where two faces meet, a dark line runs
// along their common side, but none along the diagonal that splits a rectangle into two triangles.
TEST(Meshes, EachFaceIsOneShadeAndTheFacesSidesAreDrawn) {
  const TwoSolids solids;
  render::Renderer renderer(kWidth, kHeight);
  const render::Frame& frame = renderer.draw(solids.list);
  maybe_write(frame, "mesh_two_solids");

  std::vector<int> shades;
  auto check_faces = [&](const Polyhedron& p, auto to_world, const render::Quatf& turn, const char* name) {
    for (size_t f = 0; f < p.faces.size(); ++f) {
      const Vec3f centre = p.face_centre(f);
      if (!solids.faces_camera(to_world(centre), turn * p.face_normal(f))) continue;
      const uint8_t* middle = pixel_at(frame, solids.list, to_world(centre));
      ASSERT_TRUE(is_red(middle)) << name << " face " << f;
      for (const int corner : p.faces[f]) {  // halfway to each corner: the same shade
        const Vec3f towards = centre + 0.5f * (p.corners[size_t(corner)] - centre);
        EXPECT_LE(difference(pixel_at(frame, solids.list, to_world(towards)), middle), 2) << name << " face " << f;
      }
      std::printf("%s face %zu: %3d %3d %3d\n", name, f, middle[0], middle[1], middle[2]);
      shades.push_back(brightness(middle));
    }
  };
  check_faces(solids.tetra, [&](const Vec3f& v) { return solids.tetra_world(v); }, solids.tetra_turn, "tetrahedron");
  check_faces(solids.block, [&](const Vec3f& v) { return solids.wedge_world(v); }, solids.wedge_turn, "wedge");
  ASSERT_GE(shades.size(), 4u);
  std::sort(shades.begin(), shades.end());
  EXPECT_GT(shades.back() - shades.front(), 60) << "faces turned differently are shaded differently";

  // The wedge's slope (face 4) and its front (face 0) share the side from corner 1 to corner 2.
  const Polyhedron& w = solids.block;
  const int slope = brightness(pixel_at(frame, solids.list, solids.wedge_world(w.face_centre(4))));
  const int front = brightness(pixel_at(frame, solids.list, solids.wedge_world(w.face_centre(0))));
  const Vec3f on_side = 0.5f * (w.corners[1] + w.corners[2]);
  const int line = brightness(pixel_at(frame, solids.list, solids.wedge_world(on_side)));
  std::printf("wedge: slope %d, front %d, their common side %d\n", slope, front, line);
  EXPECT_LT(line, 0.9 * std::min(slope, front));
  // The slope's diagonal, from corner 1 to corner 5: no line.
  const Vec3f on_diagonal = 0.5f * (w.corners[1] + w.corners[5]);
  EXPECT_NEAR(brightness(pixel_at(frame, solids.list, solids.wedge_world(on_diagonal))), slope, 6);
}

// A tetrahedron held up in a light from 45 degrees casts a shadow on the ground, away from the
// light, where its centre slides along the light: by both methods, the ground lit beside it.
TEST(Meshes, CastAShadowOnTheGroundByEitherMethod) {
  render::DrawList list;
  list.camera.position = {0.0f, 4.0f, 7.0f};
  list.camera.target = {-0.5f, 0.5f, 0.0f};
  list.towards_light = {1.0f, 1.0f, 0.0f};
  const Vec3f centre(0.0f, 1.5f, 0.0f);
  list.meshes.push_back(red_mesh(tetrahedron(0.9f).triangles(), centre));
  // Off the ground's grid lines (whole metres): the shadow spans x from -2.05 to -0.8, z +-0.45.
  const Vec3f in_shadow[] = {{-1.5f, 0.0f, 0.15f}, {-1.3f, 0.0f, 0.1f}, {-1.7f, 0.0f, -0.1f}};
  const Vec3f lit[] = {{1.5f, 0.0f, 0.15f}, {-1.5f, 0.0f, 0.7f}, {-2.4f, 0.0f, 0.15f}, {-0.6f, 0.0f, 0.15f}};
  for (const render::ShadowMethod method : {render::ShadowMethod::ground, render::ShadowMethod::shadow_map}) {
    render::RendererSettings settings;
    settings.shadows = method;
    render::Renderer renderer(kWidth, kHeight, settings);
    const render::Frame& frame = renderer.draw(list);
    const bool map = method == render::ShadowMethod::shadow_map;
    maybe_write(frame, map ? "mesh_shadow_map" : "mesh_shadow_ground");
    ASSERT_TRUE(is_red(pixel_at(frame, list, centre + Vec3f(0.0f, 0.0f, 0.2f)))) << "map " << map;
    const int lit_ground = brightness(pixel_at(frame, list, lit[0]));
    for (const Vec3f& at : lit)
      EXPECT_NEAR(brightness(pixel_at(frame, list, at)), lit_ground, 24) << "lit at " << at.transpose() << ", map " << map;
    for (const Vec3f& at : in_shadow)
      EXPECT_LT(brightness(pixel_at(frame, list, at)), 0.8 * lit_ground) << "shadowed at " << at.transpose() << ", map " << map;
  }
}

// Asleep, a mesh is drawn pale (less saturated) and hatched (stripes across a face), as the other bodies.
TEST(Meshes, ASleepingMeshIsPaleAndHatched) {
  TwoSolids solids;
  render::Renderer renderer(kWidth, kHeight);
  const Vec3f at = solids.wedge_world(solids.block.face_centre(4));
  auto saturation = [](const uint8_t* p) { return int(std::max({p[0], p[1], p[2]})) - int(std::min({p[0], p[1], p[2]})); };
  const render::Frame awake = renderer.draw(solids.list);
  for (render::MeshItem& mesh : solids.list.meshes) mesh.sleeping = true;
  const render::Frame asleep = renderer.draw(solids.list);
  maybe_write(asleep, "mesh_sleeping");
  EXPECT_LT(saturation(pixel_at(asleep, solids.list, at)), 0.8 * saturation(pixel_at(awake, solids.list, at)));
  const auto pixels = render::make_camera_view(solids.list.camera, kWidth, kHeight).to_pixels(at);
  ASSERT_TRUE(pixels.has_value());
  int darkest = 1000, lightest = 0;  // along 8 pixels of a row: one stripe at least
  for (int dx = 0; dx < 8; ++dx) {
    const int b = brightness(pixel(asleep, int(pixels->x()) + dx, int(pixels->y())));
    darkest = std::min(darkest, b);
    lightest = std::max(lightest, b);
  }
  EXPECT_GT(lightest - darkest, 20);
}

// Items share their triangles' GPU mesh by the vector: two items of one vector and, in a later
// frame, a new vector of other corners each draw their own, the renderer keeping no stale mesh.
TEST(Meshes, ItemsSharingTrianglesAndNewTrianglesDrawTheirOwnCorners) {
  render::DrawList list;
  list.ground = false;
  list.camera.position = {0.0f, 1.0f, 6.0f};
  list.camera.target = {0.0f, 0.5f, 0.0f};
  const Corners tetra = tetrahedron(1.0f).triangles();
  list.meshes = {red_mesh(tetra, {-1.0f, 0.5f, 0.0f}), red_mesh(tetra, {1.0f, 0.5f, 0.0f})};
  render::Renderer renderer(kWidth, kHeight);
  const render::Frame two = renderer.draw(list);
  EXPECT_TRUE(is_red(pixel_at(two, list, {-1.0f, 0.5f, 0.2f})));
  EXPECT_TRUE(is_red(pixel_at(two, list, {1.0f, 0.5f, 0.2f})));
  // The tetrahedron's apex is 0.61 m above its centre; a box-like wedge reaches 0.2 m up only.
  EXPECT_TRUE(is_red(pixel_at(two, list, {1.0f, 0.5f + 0.45f, 0.0f})));
  list.meshes = {red_mesh(wedge({1.0f, 0.4f, 1.0f}).triangles(), {1.0f, 0.5f, 0.0f})};
  const render::Frame one = renderer.draw(list);
  EXPECT_FALSE(is_red(pixel_at(one, list, {1.0f, 0.5f + 0.45f, 0.0f})));
  EXPECT_FALSE(is_red(pixel_at(one, list, {-1.0f, 0.5f, 0.2f})));
  EXPECT_TRUE(is_red(pixel_at(one, list, {1.0f, 0.5f, 0.45f})));
}

// The drawn outlines are as smooth as the other bodies' (antialias_test.cpp): the default's mean
// colour error against a 64x supersampled frame no worse than 4x multisampling's, on a standing and
// a tilted tetrahedron, two wedges and their ground shadows.
TEST(Meshes, TheirOutlinesAreAntialiasedAsWellAsFourTimesMultisampling) {
  constexpr int kSmallWidth = 320, kSmallHeight = 240;
  render::DrawList list;
  list.camera.position = {0.0f, 2.5f, 6.0f};
  list.camera.target = {0.0f, 0.6f, 0.0f};
  const Corners tetra = tetrahedron(1.1f).triangles(), block = wedge({1.2f, 0.7f, 0.8f}).triangles();
  list.meshes.push_back(red_mesh(tetra, {-1.8f, 0.23f, 0.0f}, render::Quatf(Eigen::AngleAxisf(0.3f, Vec3f::UnitY()))));
  list.meshes.push_back(red_mesh(tetra, {1.6f, 1.3f, -0.5f}, render::Quatf(Eigen::AngleAxisf(0.7f, Vec3f(1, 0, 1).normalized()))));
  list.meshes.push_back(red_mesh(block, {0.1f, 0.35f, 0.8f}, render::Quatf(Eigen::AngleAxisf(-0.6f, Vec3f::UnitY()))));
  render::MeshItem blue = red_mesh(block, {0.0f, 1.6f, -1.0f}, render::Quatf(Eigen::AngleAxisf(1.1f, Vec3f(0, 0.3f, 1).normalized())));
  blue.colour = {0.2f, 0.45f, 0.8f};
  list.meshes.push_back(blue);

  const render::RendererSettings defaults;
  render::RendererSettings msaa, none;
  msaa.antialiasing = render::Antialiasing::msaa;
  none.antialiasing = render::Antialiasing::none;
  const render::Frame reference = render::supersampled_reference(kSmallWidth, kSmallHeight, defaults, list, 8);
  auto error_with = [&](const render::RendererSettings& settings, const char* name) {
    render::Renderer renderer(kSmallWidth, kSmallHeight, settings);
    const render::Frame& frame = renderer.draw(list);
    maybe_write(frame, std::string("mesh_antialias_") + name);
    return render::mean_colour_error(frame, reference);
  };
  maybe_write(reference, "mesh_antialias_reference");
  const double edges_error = error_with(defaults, "edges"), msaa_error = error_with(msaa, "msaa"), none_error = error_with(none, "none");
  std::printf("mean colour error against 64x supersampling: edges %.4f, 4x MSAA %.4f, none %.4f\n", edges_error,
              msaa_error, none_error);
  EXPECT_LT(edges_error, 0.6 * none_error);
  EXPECT_LE(edges_error, msaa_error);
}

}  // namespace
}  // namespace impulse
