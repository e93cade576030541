#include "demos/page/page_glb.h"

#include "demos/film/marks.h"
#include "demos/film/render_types.h"
#include "demos/film/scene_draw_list.h"
#include "demos/film/world_take.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace impulse::demos {

namespace {

using physics::Quat;
using physics::Vec3;

// glTF's colour factors are linear; the scene's colours are sRGB.
double linear(double srgb) { return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4); }

// Triangles, counter-clockwise seen from the side their vertices' normals point to.
struct Geometry {
  std::vector<float> positions, normals;  // x y z per vertex
  std::vector<uint32_t> indices;

  uint32_t vertex(const Vec3& p, const Vec3& n) {
    const double length = n.norm();
    const Vec3 unit = length > 1e-12 ? Vec3(n / length) : Vec3::UnitY();
    for (int k = 0; k < 3; ++k) positions.push_back(float(p[k])), normals.push_back(float(unit[k]));
    return uint32_t(positions.size() / 3 - 1);
  }
  Vec3 position(uint32_t i) const { return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]}; }
  Vec3 normal(uint32_t i) const { return {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]}; }
  // Turned to face its corners' normals; none where its corners are in a line (a sphere's poles).
  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    const Vec3 face = (position(b) - position(a)).cross(position(c) - position(a));
    if (face.norm() < 1e-14) return;
    if (face.dot(normal(a) + normal(b) + normal(c)) < 0) std::swap(b, c);
    indices.insert(indices.end(), {a, b, c});
  }
  // A flat polygon (corners in order either way round), fanned from its first corner.
  void polygon(const std::vector<Vec3>& corners, const Vec3& n) {
    std::vector<uint32_t> at;
    for (const Vec3& p : corners) at.push_back(vertex(p, n));
    for (size_t k = 1; k + 1 < at.size(); ++k) triangle(at[0], at[k], at[k + 1]);
  }
  // Rows of vertices, each `segments + 1` long (its last at its first's place), joined row to row.
  void join_rows(uint32_t first, int rows, int segments) {
    for (int i = 0; i + 1 < rows; ++i)
      for (int j = 0; j < segments; ++j) {
        const uint32_t a = first + uint32_t(i * (segments + 1) + j), b = a + 1, c = a + uint32_t(segments + 1), d = c + 1;
        triangle(a, c, b);
        triangle(b, c, d);
      }
  }
};

constexpr int kSegments = 32;  // around a sphere's, capsule's or cylinder's axis
constexpr int kRings = 16;     // pole to pole

// The point of a unit sphere at `ring` of kRings from +y and `segment` of kSegments around y.
Vec3 on_sphere(int ring, int segment) {
  const double theta = std::numbers::pi * ring / kRings, phi = 2 * std::numbers::pi * segment / kSegments;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

// A sphere of `radius`, or a capsule when `half_height` > 0: the top half raised and the bottom
// half lowered by it, the equator's row twice, joined by the side.
void round_body(Geometry& g, double radius, double half_height) {
  const uint32_t first = uint32_t(g.positions.size() / 3);
  int rows = 0;
  for (int ring = 0; ring <= kRings; ++ring) {
    std::vector<double> shifts{half_height};
    if (half_height > 0 && ring > kRings / 2) shifts = {-half_height};
    if (half_height > 0 && ring == kRings / 2) shifts = {half_height, -half_height};
    for (const double shift : shifts) {
      for (int segment = 0; segment <= kSegments; ++segment) {
        const Vec3 d = on_sphere(ring, segment);
        g.vertex(radius * d + Vec3(0, shift, 0), d);
      }
      ++rows;
    }
  }
  g.join_rows(first, rows, kSegments);
}

void cylinder(Geometry& g, double radius, double half_height) {
  const uint32_t first = uint32_t(g.positions.size() / 3);
  for (const double y : {half_height, -half_height})
    for (int segment = 0; segment <= kSegments; ++segment) {
      const Vec3 d = on_sphere(kRings / 2, segment);
      g.vertex(radius * d + Vec3(0, y, 0), d);
    }
  g.join_rows(first, 2, kSegments);
  for (const double y : {half_height, -half_height}) {
    std::vector<Vec3> cap;
    for (int segment = 0; segment < kSegments; ++segment) cap.push_back(radius * on_sphere(kRings / 2, segment) + Vec3(0, y, 0));
    g.polygon(cap, Vec3(0, y, 0));
  }
}

void box(Geometry& g, const Vec3& h) {
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {1.0, -1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<Vec3> corners;
      constexpr int kSigns[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& signs : kSigns) {
        Vec3 p = Vec3::Zero();
        p[axis] = side * h[axis];
        p[u] = signs[0] * h[u];
        p[v] = signs[1] * h[v];
        corners.push_back(p);
      }
      g.polygon(corners, side * Vec3::Unit(axis));
    }
}

void hull(Geometry& g, const physics::Hull& hull) {
  for (const physics::HullFace& face : hull.faces) {
    std::vector<Vec3> corners;
    for (int k = 0; k < face.count; ++k) corners.push_back(hull.corners[size_t(hull.corner_of(face, k))]);
    Vec3 n = Vec3::Zero();  // Newell's: the polygon's area vector, outwards for corners counter-clockwise from outside
    for (size_t k = 0; k < corners.size(); ++k) n += corners[k].cross(corners[(k + 1) % corners.size()]);
    g.polygon(corners, n);
  }
}

void mesh(Geometry& g, const physics::Mesh& mesh) {
  for (const physics::MeshTriangle& triangle : mesh.triangles) {
    const Vec3 &a = mesh.vertices[size_t(triangle.corners[0])], &b = mesh.vertices[size_t(triangle.corners[1])],
               &c = mesh.vertices[size_t(triangle.corners[2])];
    g.polygon({a, b, c}, (b - a).cross(c - a));
  }
}

// An arrow 1 long along +y from the origin: a shaft of radius kShaft, then a cone of radius kHead
// over its last kHeadShare. An arrow shorter than kFullWidth m is drawn thinner in proportion.
constexpr double kShaft = 0.02, kHead = 0.05, kHeadShare = 0.25, kFullWidth = 0.4;
void arrow(Geometry& g) {
  const double neck = 1 - kHeadShare;
  const Vec3 down(0, -1, 0);
  uint32_t first = uint32_t(g.positions.size() / 3);
  for (const double y : {neck, 0.0})
    for (int segment = 0; segment <= kSegments; ++segment) {
      const Vec3 d = on_sphere(kRings / 2, segment);
      g.vertex(kShaft * d + Vec3(0, y, 0), d);
    }
  g.join_rows(first, 2, kSegments);
  first = uint32_t(g.positions.size() / 3);
  for (const double y : {1.0, neck})  // the cone's side: its tip as a row of its own
    for (int segment = 0; segment <= kSegments; ++segment) {
      const Vec3 d = on_sphere(kRings / 2, segment);
      g.vertex((y == 1.0 ? 0.0 : kHead) * d + Vec3(0, y, 0), kHeadShare * d + kHead * Vec3::UnitY());
    }
  g.join_rows(first, 2, kSegments);
  for (const double y : {0.0, neck}) {
    std::vector<Vec3> cap;
    for (int segment = 0; segment < kSegments; ++segment) cap.push_back((y == 0 ? kShaft : kHead) * on_sphere(kRings / 2, segment) + Vec3(0, y, 0));
    g.polygon(cap, down);
  }
}

// The kind of mark an arrow of `colour` is (marks.h), "... faint" where it is that mark's colour
// faded towards white (a resting contact's).
std::string arrow_kind(const render::Colour& colour) {
  const std::pair<render::Colour, const char*> kinds[] = {{mark_colour::contact_normal, "normal"},
                                                          {mark_colour::normal_impulse, "impulse"},
                                                          {mark_colour::friction_impulse, "friction"},
                                                          {mark_colour::velocity, "velocity"}};
  const float c[3] = {colour.r, colour.g, colour.b};
  for (const auto& [mark, name] : kinds) {
    const float m[3] = {mark.r, mark.g, mark.b};
    float fade = NAN;  // c = m + (1 - m) fade in every channel
    bool faded = true;
    for (int k = 0; k < 3; ++k) {
      if (1 - m[k] < 1e-3f) {
        faded = faded && std::abs(c[k] - m[k]) < 1e-4f;
        continue;
      }
      const float f = (c[k] - m[k]) / (1 - m[k]);
      if (std::isnan(fade)) fade = f;
      faded = faded && std::abs(f - fade) < 1e-3f;
    }
    if (faded && std::abs(fade) < 1e-4f) return name;
    if (faded && fade > 0 && fade < 1) return std::string(name) + " faint";
  }
  return "arrow";
}

// A plane as a square of side `size` in it, centred on the point of it nearest `centre`, facing
// its normal. World coordinates: a plane's node has no transform.
void plane(Geometry& g, const physics::Shape& shape, const Vec3& centre, double size) {
  const Vec3 n = shape.normal.normalized();
  const Vec3 middle = centre - (n.dot(centre) - shape.offset) * n;
  const Vec3 u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized(), v = n.cross(u);
  const double h = size / 2;
  g.polygon({middle - h * u - h * v, middle + h * u - h * v, middle + h * u + h * v, middle - h * u + h * v}, n);
}

// The glTF model, its one buffer filled as accessors are added.
class GlbBuilder {
 public:
  GlbBuilder() {
    model_.asset.generator = "impulse";
    model_.buffers.emplace_back();
  }
  tinygltf::Model& model() { return model_; }

  // Floats, `width` per element (1, 3 or 4), with their bounds (POSITION's and an animation
  // input's must have them).
  int floats(const std::vector<float>& values, int width, int target) {
    const int type = width == 1 ? TINYGLTF_TYPE_SCALAR : width == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
    tinygltf::Accessor accessor = make(view(values.data(), values.size() * sizeof(float), target), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                       values.size() / size_t(width), type);
    accessor.minValues.assign(size_t(width), HUGE_VAL);
    accessor.maxValues.assign(size_t(width), -HUGE_VAL);
    for (size_t i = 0; i < values.size(); ++i) {
      double& low = accessor.minValues[i % size_t(width)];
      double& high = accessor.maxValues[i % size_t(width)];
      low = std::min(low, double(values[i]));
      high = std::max(high, double(values[i]));
    }
    model_.accessors.push_back(std::move(accessor));
    return int(model_.accessors.size() - 1);
  }

  // Triangle indices, 16-bit where the vertices allow.
  int indices(const std::vector<uint32_t>& values, size_t vertices) {
    if (vertices <= 0xffff) {
      const std::vector<uint16_t> small(values.begin(), values.end());
      model_.accessors.push_back(make(view(small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, small.size(), TINYGLTF_TYPE_SCALAR));
    } else {
      model_.accessors.push_back(make(view(values.data(), values.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, values.size(), TINYGLTF_TYPE_SCALAR));
    }
    return int(model_.accessors.size() - 1);
  }

  int mesh(const Geometry& g, int material, const std::string& name) {
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = floats(g.positions, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["NORMAL"] = floats(g.normals, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.indices = indices(g.indices, g.positions.size() / 3);
    primitive.material = material;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(primitive));
    model_.meshes.push_back(std::move(mesh));
    return int(model_.meshes.size() - 1);
  }

  // The mesh `of`'s geometry again with another material.
  int mesh_like(int of, int material, const std::string& name) {
    tinygltf::Mesh mesh = model_.meshes.at(size_t(of));
    mesh.name = name;
    mesh.primitives.at(0).material = material;
    model_.meshes.push_back(std::move(mesh));
    return int(model_.meshes.size() - 1);
  }

  // A material of an sRGB colour (glTF's factors are linear), named by it, not metal.
  template <class C>
  static tinygltf::Material coloured(const char* kind, const C& colour) {
    tinygltf::Material material;
    char name[64];
    std::snprintf(name, sizeof name, "%s %.3f %.3f %.3f", kind, colour.r, colour.g, colour.b);
    material.name = name;
    material.pbrMetallicRoughness.baseColorFactor = {linear(colour.r), linear(colour.g), linear(colour.b), 1.0};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    return material;
  }

  // A flat colour: unlit where the viewer knows KHR_materials_unlit, else matte.
  int unlit(const render::Colour& colour) {
    tinygltf::Material material = coloured("unlit sRGB", colour);
    material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
    if (std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), "KHR_materials_unlit") == model_.extensionsUsed.end())
      model_.extensionsUsed.push_back("KHR_materials_unlit");
    model_.materials.push_back(std::move(material));
    return int(model_.materials.size() - 1);
  }

  // One material per sRGB colour and sidedness.
  int material(const Colour& colour, bool double_sided) {
    const auto key = std::make_tuple(colour.r, colour.g, colour.b, double_sided);
    if (const auto found = materials_.find(key); found != materials_.end()) return found->second;
    tinygltf::Material material = coloured("sRGB", colour);
    material.pbrMetallicRoughness.roughnessFactor = 0.6;  // as the page's viewer draws the bodies
    material.doubleSided = double_sided;
    model_.materials.push_back(std::move(material));
    return materials_[key] = int(model_.materials.size() - 1);
  }

 private:
  // A buffer view of `bytes` at the buffer's end, which stays a multiple of 4 bytes long.
  int view(const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), begin, begin + bytes);
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    model_.bufferViews.push_back(std::move(view));
    return int(model_.bufferViews.size() - 1);
  }
  static tinygltf::Accessor make(int view, int component, size_t count, int type) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.byteOffset = 0;
    accessor.componentType = component;
    accessor.count = count;
    accessor.type = type;
    return accessor;
  }

  tinygltf::Model model_;
  std::map<std::tuple<float, float, float, bool>, int> materials_;
};

// A key for the meshes bodies may share: the shape's sizes (a hull's or mesh's data) and material.
std::string shape_key(const physics::Shape& s, int material) {
  char key[256];
  std::snprintf(key, sizeof key, "%d %.17g %.17g %.17g %.17g %.17g %p %d", int(s.type), s.radius, s.half_height, s.half_extents.x(),
                s.half_extents.y(), s.half_extents.z(), static_cast<const void*>(s.data.get()), material);
  return key;
}

}  // namespace

void write_glb(const Scene& scene, std::ostream& out, bool marks) {
  WorldTake take(scene);
  const int fps = scene.video.fps;
  // The frames the page samples (write_run_json), as the video's at real speed.
  const long frames = std::max(1L, std::lround(std::ceil(scene.duration * fps - 0.5)));
  const std::vector<physics::Body>& bodies = take.bodies();
  const size_t count = bodies.size();

  // Every frame's poses: x y z, then the quaternion x y z w (glTF's order), each body's kept on the
  // same side of the quaternion's double cover as the frame before, so that interpolating between
  // frames turns the short way.
  std::vector<double> poses(size_t(frames) * count * 7);
  // Each rod or rope (a distance joint), drawn as the video draws it from anchor to anchor: a unit
  // rod along y, per frame moved to the anchors' midpoint, turned onto the line between them and
  // stretched to its length (x y z, quaternion x y z w, scale x y z).
  std::vector<const physics::Joint*> rods;
  for (const physics::Joint& joint : take.joints())
    if (joint.type == physics::JointType::distance) rods.push_back(&joint);
  std::vector<double> rod_poses(size_t(frames) * rods.size() * 10);
  // What the video marks on each frame, drawn once the run's arrow scales are known.
  struct Marked {
    std::vector<BodyPose> poses;
    std::vector<Vec3> velocities;
    std::vector<physics::ContactRecord> contacts;
  };
  std::vector<Marked> marked;
  FrameSample sample;
  for (long k = 0; k < frames; ++k) {
    const double time = double(k) / fps;
    while (!take.finished() && take.time() < time - 1e-9) take.step();
    take.sample(time, time, sample);
    for (size_t i = 0; i < count; ++i) {
      double* pose = &poses[(size_t(k) * count + i) * 7];
      const Quat q = sample.poses[i].orientation.normalized();
      double sign = 1;
      if (k > 0) {
        const double* before = pose - count * 7;
        if (q.x() * before[3] + q.y() * before[4] + q.z() * before[5] + q.w() * before[6] < 0) sign = -1;
      }
      const double values[7] = {sample.poses[i].position.x(), sample.poses[i].position.y(), sample.poses[i].position.z(),
                                sign * q.x(), sign * q.y(), sign * q.z(), sign * q.w()};
      std::copy(values, values + 7, pose);
    }
    for (size_t r = 0; r < rods.size(); ++r) {
      auto anchor = [&](int body, const Vec3& local) {
        return body < 0 ? local : Vec3(sample.poses[size_t(body)].position + sample.poses[size_t(body)].orientation * local);
      };
      const Vec3 a = anchor(rods[r]->body_a, rods[r]->local_anchor_a), b = anchor(rods[r]->body_b, rods[r]->local_anchor_b);
      const double length = (b - a).norm();
      Quat q = length > 1e-9 ? Quat::FromTwoVectors(Vec3::UnitY(), b - a) : Quat::Identity();
      q.normalize();
      double* pose = &rod_poses[(size_t(k) * rods.size() + r) * 10];
      if (k > 0) {
        const double* before = pose - rods.size() * 10;
        if (q.x() * before[3] + q.y() * before[4] + q.z() * before[5] + q.w() * before[6] < 0) q.coeffs() = -q.coeffs();
      }
      const Vec3 middle = (a + b) / 2;
      const double values[10] = {middle.x(), middle.y(), middle.z(), q.x(), q.y(), q.z(), q.w(), 1, std::max(length, 1e-6), 1};
      std::copy(values, values + 10, pose);
    }
    if (marks) marked.push_back({sample.poses, sample.velocities, sample.contacts});
  }

  // The video's arrows per frame, as the page's marks (page_export.cpp): its draw list at the
  // scene's camera, each body's velocity the frame's.
  std::vector<std::vector<render::ArrowItem>> arrows;
  if (marks) {
    const ArrowScales scales = arrow_scales(scene, take.summary());
    std::vector<physics::Body> moving = take.bodies();
    for (const Marked& frame : marked) {
      for (size_t i = 0; i < count; ++i) moving[i].velocity = frame.velocities[i];
      arrows.push_back(scene_draw_list(scene, moving, frame.poses, take.joints(), frame.contacts, scales, to_render(scene.camera)).arrows);
    }
  }

  GlbBuilder builder;
  tinygltf::Model& model = builder.model();
  tinygltf::Scene world;
  world.name = scene.title;

  // Planes: squares centred below the camera's target, wide enough for every body's start.
  const Vec3 target = scene.camera.target.cast<double>();
  double reach = 20;
  for (size_t i = 0; i < count; ++i)
    if (bodies[i].shape.type != physics::ShapeType::plane) reach = std::max(reach, (Eigen::Map<const Vec3>(&poses[i * 7]) - target).norm() + 10);

  std::map<std::string, int> meshes;
  for (size_t i = 0; i < count; ++i) {
    const physics::Body& body = bodies[i];
    const physics::Shape& shape = body.shape;
    const bool ground = shape.type == physics::ShapeType::plane && shape.normal.normalized().y() > 0.999;
    const int material = builder.material(ground ? Colour{0.84f, 0.85f, 0.86f} : scene.colours[i], shape.type == physics::ShapeType::mesh);
    tinygltf::Node node;
    node.name = body.name;
    const std::string key = shape_key(shape, material);
    if (const auto found = meshes.find(key); found != meshes.end() && shape.type != physics::ShapeType::plane) {
      node.mesh = found->second;
    } else {
      Geometry g;
      switch (shape.type) {
        case physics::ShapeType::sphere: round_body(g, shape.radius, 0); break;
        case physics::ShapeType::capsule: round_body(g, shape.radius, shape.half_height); break;
        case physics::ShapeType::cylinder: cylinder(g, shape.radius, shape.half_height); break;
        case physics::ShapeType::box: box(g, shape.half_extents); break;
        case physics::ShapeType::hull: hull(g, *shape.hull()); break;
        case physics::ShapeType::mesh: mesh(g, *shape.mesh()); break;
        case physics::ShapeType::plane: plane(g, shape, target, 2 * reach); break;
      }
      node.mesh = meshes[key] = builder.mesh(g, material, physics::shape_name(shape.type));
    }
    if (shape.type != physics::ShapeType::plane) {  // a plane is where its normal and offset put it, in the world
      const double* pose = &poses[i * 7];
      node.translation.assign(pose, pose + 3);
      node.rotation.assign(pose + 3, pose + 7);
    }
    model.nodes.push_back(std::move(node));
    world.nodes.push_back(int(model.nodes.size() - 1));
  }

  // The rods, in a node of their own ("joints") that a viewer can hide.
  std::vector<int> rod_nodes;
  if (!rods.empty()) {
    Geometry g;
    cylinder(g, 0.006, 0.5);
    const int rod_mesh = builder.mesh(g, builder.material(Colour{0.45f, 0.45f, 0.47f}, false), "rod");
    tinygltf::Node joints;
    joints.name = "joints";
    for (size_t r = 0; r < rods.size(); ++r) {
      tinygltf::Node node;
      node.name = rods[r]->name;
      node.mesh = rod_mesh;
      const double* pose = &rod_poses[r * 10];
      node.translation.assign(pose, pose + 3);
      node.rotation.assign(pose + 3, pose + 7);
      node.scale.assign(pose + 7, pose + 10);
      model.nodes.push_back(std::move(node));
      rod_nodes.push_back(int(model.nodes.size() - 1));
      joints.children.push_back(rod_nodes.back());
    }
    model.nodes.push_back(std::move(joints));
    world.nodes.push_back(int(model.nodes.size() - 1));
  }

  // The scene's camera as the video's starts, looking down its local -z with the video's up.
  {
    const Vec3 eye = scene.camera.position.cast<double>();
    const Vec3 back = (eye - target).normalized();
    const Vec3 up = std::abs(back.y()) > 0.999 ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitY());
    const Vec3 right = up.cross(back).normalized();
    physics::Mat3 axes;
    axes << right, back.cross(right), back;
    const Quat q = Quat(axes).normalized();
    tinygltf::Camera camera;
    camera.name = "camera";
    camera.type = "perspective";
    camera.perspective.yfov = scene.camera.fov_y_degrees * std::numbers::pi / 180;
    camera.perspective.aspectRatio = double(scene.video.width) / scene.video.height;
    camera.perspective.znear = 0.05;
    camera.perspective.zfar = 2000;
    model.cameras.push_back(std::move(camera));
    tinygltf::Node node;
    node.name = "camera";
    node.camera = 0;
    node.translation = {eye.x(), eye.y(), eye.z()};
    node.rotation = {q.x(), q.y(), q.z(), q.w()};
    model.nodes.push_back(std::move(node));
    world.nodes.push_back(int(model.nodes.size() - 1));
  }

  // The arrows: per kind (colour) its slots, each slot's pose per frame (x y z, quaternion x y z w,
  // scale x y z), a frame's arrows of a kind in its first slots, the rest at scale 0.
  struct Kind {
    render::Colour colour;
    std::string name;
    size_t slots = 0;
    std::vector<double> poses;  // frames × slots × 10
    std::vector<int> nodes;
  };
  std::vector<Kind> kinds;
  auto kind_of = [&](const render::Colour& c) {
    size_t k = 0;
    while (k < kinds.size() && !(kinds[k].colour.r == c.r && kinds[k].colour.g == c.g && kinds[k].colour.b == c.b)) ++k;
    if (k == kinds.size()) kinds.push_back({c, arrow_kind(c), 0, {}, {}});
    return k;
  };
  for (const auto& frame : arrows) {
    std::vector<size_t> used(kinds.size());
    for (const render::ArrowItem& a : frame) {
      const size_t k = kind_of(a.colour);
      used.resize(kinds.size());
      kinds[k].slots = std::max(kinds[k].slots, ++used[k]);
    }
  }
  for (Kind& kind : kinds) {
    kind.poses.resize(size_t(frames) * kind.slots * 10, 0.0);
    for (size_t at = 6; at < kind.poses.size(); at += 10) kind.poses[at] = 1;  // w
  }
  for (size_t k = 0; k < arrows.size(); ++k) {
    std::vector<size_t> used(kinds.size());
    for (const render::ArrowItem& a : arrows[k]) {
      const size_t n = kind_of(a.colour);
      Kind& kind = kinds[n];
      const Vec3 origin = a.origin.cast<double>(), along = a.direction.cast<double>();
      const double length = along.norm();
      const Quat q = Quat::FromTwoVectors(Vec3::UnitY(), along).normalized();
      const double side = std::min(1.0, length / kFullWidth);
      const double values[10] = {origin.x(), origin.y(), origin.z(), q.x(), q.y(), q.z(), q.w(), side, length, side};
      std::copy(values, values + 10, &kind.poses[(k * kind.slots + used[n]++) * 10]);
    }
  }
  if (marks) {
    tinygltf::Node group;
    group.name = "marks";
    Geometry g;
    arrow(g);
    int first = -1;  // the arrow's geometry, written once
    for (Kind& kind : kinds) {
      const int material = builder.unlit(kind.colour);
      const int mesh = first < 0 ? builder.mesh(g, material, "arrow " + kind.name) : builder.mesh_like(first, material, "arrow " + kind.name);
      if (first < 0) first = mesh;
      tinygltf::Node parent;
      parent.name = kind.name;
      for (size_t slot = 0; slot < kind.slots; ++slot) {
        tinygltf::Node node;
        node.name = kind.name + " " + std::to_string(slot + 1);
        node.mesh = mesh;
        const double* pose = &kind.poses[slot * 10];
        node.translation.assign(pose, pose + 3);
        node.rotation.assign(pose + 3, pose + 7);
        node.scale.assign(pose + 7, pose + 10);
        model.nodes.push_back(std::move(node));
        kind.nodes.push_back(int(model.nodes.size() - 1));
        parent.children.push_back(kind.nodes.back());
      }
      model.nodes.push_back(std::move(parent));
      group.children.push_back(int(model.nodes.size() - 1));
    }
    model.nodes.push_back(std::move(group));
    world.nodes.push_back(int(model.nodes.size() - 1));
  }

  // The animation: the bodies and rods whose pose changes, each frame's translation and rotation
  // (and a rod's scale).
  tinygltf::Animation run;
  run.name = "run";
  int times = -1;
  // The values `data[first + k * stride + c]` for frames k and c in [from, from + width).
  auto channel = [&](int node, const char* path, const std::vector<double>& data, size_t first, size_t stride, int from, int width,
                     const char* interpolation = "LINEAR") {
    if (times < 0) {
      std::vector<float> seconds;
      for (long k = 0; k < frames; ++k) seconds.push_back(float(double(k) / fps));
      times = builder.floats(seconds, 1, 0);
    }
    std::vector<float> values;
    for (long k = 0; k < frames; ++k)
      for (int c = from; c < from + width; ++c) values.push_back(float(data[first + size_t(k) * stride + size_t(c)]));
    tinygltf::AnimationSampler sampler;
    sampler.input = times;
    sampler.output = builder.floats(values, width, 0);
    sampler.interpolation = interpolation;
    run.samplers.push_back(std::move(sampler));
    tinygltf::AnimationChannel aim;
    aim.sampler = int(run.samplers.size() - 1);
    aim.target_node = node;
    aim.target_path = path;
    run.channels.push_back(std::move(aim));
  };
  auto moves = [&](const std::vector<double>& data, size_t first, size_t stride, size_t width) {
    for (long k = 1; k < frames; ++k)
      if (!std::equal(&data[first], &data[first] + width, &data[first + size_t(k) * stride])) return true;
    return false;
  };
  for (size_t i = 0; i < count; ++i)
    if (moves(poses, i * 7, count * 7, 7)) {
      channel(int(i), "translation", poses, i * 7, count * 7, 0, 3);
      channel(int(i), "rotation", poses, i * 7, count * 7, 3, 4);
    }
  for (size_t r = 0; r < rods.size(); ++r)
    if (moves(rod_poses, r * 10, rods.size() * 10, 10)) {
      channel(rod_nodes[r], "translation", rod_poses, r * 10, rods.size() * 10, 0, 3);
      channel(rod_nodes[r], "rotation", rod_poses, r * 10, rods.size() * 10, 3, 4);
      channel(rod_nodes[r], "scale", rod_poses, r * 10, rods.size() * 10, 7, 3);
    }
  for (const Kind& kind : kinds)  // stepped: an arrow is the frame's until the next
    for (size_t slot = 0; slot < kind.slots; ++slot) {
      const size_t stride = kind.slots * 10;
      channel(kind.nodes[slot], "translation", kind.poses, slot * 10, stride, 0, 3, "STEP");
      channel(kind.nodes[slot], "rotation", kind.poses, slot * 10, stride, 3, 4, "STEP");
      channel(kind.nodes[slot], "scale", kind.poses, slot * 10, stride, 7, 3, "STEP");
    }
  if (!run.channels.empty()) model.animations.push_back(std::move(run));

  model.scenes.push_back(std::move(world));
  model.defaultScene = 0;
  if (model.buffers[0].data.empty()) model.buffers.clear();
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true) || !out) throw std::runtime_error("cannot write the glb");
}

}  // namespace impulse::demos
