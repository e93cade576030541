// Narrow phase of the convex pairs without a formula of their own (a capsule, a cylinder or a hull
// against a box, a capsule, a cylinder or a hull): the normal and depth by GJK and EPA (libccd), then the points by
// clipping, as Jolt's and Box3D's manifolds are built:
//   1. GJK on both shapes grown by half the margin: they overlap exactly where the surfaces are
//      closer than the margin. The normal: of EPA's direction, MPR's and the faces' normals, the
//      one along which the shapes are farthest apart (the separating axes' rule).
//   2. Each shape's feature facing the other (supporting_feature): a face (a box's, a hull's, a
//      cylinder's flat face as an octagon of rim points), a line (a capsule's side: its ends' balls; a
//      cylinder's side: the two rims' lowest points) or a point.
//   3. Where a face's normal is the pair's normal within kFaceAngle, it is the reference: the other
//      feature's points are clipped to the face's sides and measured from its plane, along its
//      normal (exact: resting stays resting). Two round cores (capsules, cylinders' sides) touch
//      along the line between their closest points, two lines side by side at their overlap's ends.
//      Otherwise EPA's one point.
#include "physics/collide.h"
#include "physics/manifold.h"

#include <ccd/ccd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace impulse::physics {

namespace {

constexpr Real kFaceCos = 0.99939;     // cos 2 degrees: a face's normal this close is the pair's
constexpr Real kLineSin = 0.17365;     // sin 10 degrees: a round side this close across the normal touches along a line
constexpr Real kParallelCos = 0.99619; // cos 5 degrees: two round lines this close lie side by side
constexpr int kMostPoints = 8;

// A shape where it is, grown by `grow` all round (libccd's object).
struct Placed {
  const Shape* shape;
  Vec3 position;
  Mat3 rotation;
  Real grow;
};

Vec3 local_support(const Shape& s, const Vec3& d) {
  const Real y = d.y() < 0 ? -s.half_height : s.half_height;
  switch (s.type) {
    case ShapeType::box:
      return {d.x() < 0 ? -s.half_extents.x() : s.half_extents.x(), d.y() < 0 ? -s.half_extents.y() : s.half_extents.y(),
              d.z() < 0 ? -s.half_extents.z() : s.half_extents.z()};
    case ShapeType::capsule: return Vec3(0, y, 0) + s.radius * d.normalized();
    case ShapeType::cylinder: {
      const Real across = std::hypot(d.x(), d.z());
      return across > Real(1e-12) ? Vec3(s.radius * d.x() / across, y, s.radius * d.z() / across) : Vec3(0, y, 0);
    }
    case ShapeType::hull: {
      const std::vector<Vec3>& corners = s.hull()->corners;
      size_t best = 0;
      for (size_t i = 1; i < corners.size(); ++i)
        if (corners[i].dot(d) > corners[best].dot(d)) best = i;
      return corners[best];
    }
    default: return Vec3::Zero();
  }
}

void ccd_support(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out) {
  const Placed& p = *static_cast<const Placed*>(object);
  const Vec3 d(ccdVec3X(direction), ccdVec3Y(direction), ccdVec3Z(direction));
  const Vec3 local = local_support(*p.shape, p.rotation.transpose() * d);
  const Vec3 world = p.position + p.rotation * local + p.grow * d.normalized();
  ccdVec3Set(out, world.x(), world.y(), world.z());
}

void ccd_centre(const void* object, ccd_vec3_t* out) {
  const Placed& p = *static_cast<const Placed*>(object);
  ccdVec3Set(out, p.position.x(), p.position.y(), p.position.z());
}

// The points of a shape's feature farthest along a unit direction, in the world.
struct Feature {
  std::array<Vec3, kMostPoints> points;
  int count = 0;
  bool face = false;     // a flat face: its normal is `face_normal` (outward)
  Vec3 face_normal = Vec3::Zero();
  bool round = false;    // the points lie on a round surface (manifold.h's round bit)
  // Where the points are a core grown by `radius` (a capsule's segment or one end, a cylinder's
  // axis under its side): the core's ends (equal for one point), `cored` set.
  bool cored = false;
  Vec3 core[2];
  Real radius = 0;
  void add(const Vec3& p) { points[count++] = p; }
};

Feature supporting_feature(const Body& body, const Mat3& rotation, const Vec3& dir) {
  const Shape& s = body.shape;
  const Vec3 d = rotation.transpose() * dir;
  Feature f;
  auto world = [&](const Vec3& local) { return Vec3(body.position + rotation * local); };
  switch (s.type) {
    case ShapeType::box: {  // the face most along d (the incident face of box_box)
      int axis = 0;
      d.cwiseAbs().maxCoeff(&axis);
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const Real sign = d[axis] < 0 ? -1 : 1;
      const Real su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};
      for (int k = 0; k < 4; ++k) {
        Vec3 corner;
        corner[axis] = sign * s.half_extents[axis];
        corner[u] = su[k] * s.half_extents[u];
        corner[v] = sv[k] * s.half_extents[v];
        f.add(world(corner));
      }
      f.face = true;
      f.face_normal = rotation.col(axis) * sign;
      return f;
    }
    case ShapeType::capsule: {
      f.round = f.cored = true;
      f.radius = s.radius;
      const Vec3 out = s.radius * d.normalized();
      if (std::abs(d.y()) < kLineSin * d.norm()) {
        f.core[0] = world(Vec3(0, -s.half_height, 0));
        f.core[1] = world(Vec3(0, s.half_height, 0));
        f.add(world(Vec3(0, -s.half_height, 0) + out));
        f.add(world(Vec3(0, s.half_height, 0) + out));
      } else {
        f.core[0] = f.core[1] = world(Vec3(0, d.y() < 0 ? -s.half_height : s.half_height, 0));
        f.add(world(local_support(s, d)));
      }
      return f;
    }
    case ShapeType::cylinder: {
      const Real y = d.y() < 0 ? -s.half_height : s.half_height;
      const Real across = std::hypot(d.x(), d.z());
      if (across < kLineSin * d.norm()) {  // a flat face: an octagon of rim points fixed in the body
        for (int k = 0; k < 8; ++k) {
          const Real angle = k * std::numbers::pi / 4;
          f.add(world(Vec3(s.radius * std::cos(angle), y, s.radius * std::sin(angle))));
        }
        f.face = true;
        f.face_normal = rotation.col(1) * (y < 0 ? -1 : 1);
        return f;
      }
      f.round = true;
      const Vec3 out(s.radius * d.x() / across, 0, s.radius * d.z() / across);
      if (std::abs(d.y()) < kLineSin * d.norm()) {
        f.cored = true;
        f.radius = s.radius;
        f.core[0] = world(Vec3(0, -s.half_height, 0));
        f.core[1] = world(Vec3(0, s.half_height, 0));
        f.add(world(Vec3(0, -s.half_height, 0) + out));
        f.add(world(Vec3(0, s.half_height, 0) + out));
      } else {
        f.add(world(Vec3(0, y, 0) + out));
      }
      return f;
    }
    case ShapeType::hull: {  // the face most along d: its corners, or its quad where it has more than four
      const Hull& hull = *s.hull();
      int best = 0;
      for (int k = 1; k < int(hull.faces.size()); ++k)
        if (hull.faces[k].normal.dot(d) > hull.faces[best].normal.dot(d)) best = k;
      const HullFace& face = hull.faces[best];
      if (face.count > 4)
        for (const Vec3& q : face.quad) f.add(world(q));
      else
        for (int k = 0; k < face.count; ++k) f.add(world(hull.corners[hull.corner_of(face, k)]));
      f.face = true;
      f.face_normal = rotation * face.normal;
      return f;
    }
    default: return f;
  }
}

// The closest points of segments p0-p1 and q0-q1 (either may be a point): Ericson, "Real-Time
// Collision Detection", 5.1.9.
void closest_points(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& on_p, Vec3& on_q) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const Real a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr Real kTiny = 1e-18;
  Real s = 0, t = 0;
  if (a <= kTiny && e <= kTiny) {
  } else if (a <= kTiny) {
    t = std::clamp(f / e, Real(0), Real(1));
  } else {
    const Real c = d1.dot(r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, Real(0), Real(1));
    } else {
      const Real b = d1.dot(d2), denom = a * e - b * b;
      s = denom > kTiny ? std::clamp((b * f - c * e) / denom, Real(0), Real(1)) : 0;
      t = (b * s + f) / e;
      if (t < 0) t = 0, s = std::clamp(-c / a, Real(0), Real(1));
      else if (t > 1) t = 1, s = std::clamp((b - c) / a, Real(0), Real(1));
    }
  }
  on_p = p0 + d1 * s;
  on_q = q0 + d2 * t;
}

// A point with the id that names it across steps: an incident point's index, or 16 + 8 * edge +
// side where the incident polygon's edge crosses the reference face's side.
struct Clipped {
  Vec3 x;
  int id;
};

// Sutherland-Hodgman: the incident points inside every side of the reference face (the planes
// through its edges along its normal).
int clip_to_face(const Feature& reference, const Feature& incident, std::array<Clipped, 32>& out) {
  std::array<Clipped, 32> a, b;
  int n = 0;
  for (int i = 0; i < incident.count; ++i) a[n++] = {incident.points[i], i};
  Vec3 centroid = Vec3::Zero();
  for (int k = 0; k < reference.count; ++k) centroid += reference.points[k];
  centroid /= reference.count;
  for (int side = 0; side < reference.count && n > 0; ++side) {
    const Vec3& p0 = reference.points[side];
    const Vec3& p1 = reference.points[(side + 1) % reference.count];
    Vec3 inward = reference.face_normal.cross(p1 - p0);
    if (inward.dot(centroid - p0) < 0) inward = -inward;
    auto inside = [&](const Vec3& x) { return inward.dot(x - p0) >= 0; };
    int m = 0;
    if (n <= 2 && inside(a[0].x)) b[m++] = a[0];  // a point or a line: its first end; a polygon's come as ends of edges
    const int edges = n == 1 ? 0 : n == 2 ? 1 : n;
    for (int i = 0; i < edges && m < 30; ++i) {
      const Clipped& from = a[i];
      const Clipped& to = a[(i + 1) % n];
      const Real df = inward.dot(from.x - p0), dt = inward.dot(to.x - p0);
      if ((df < 0) != (dt < 0)) b[m++] = {from.x + (to.x - from.x) * (df / (df - dt)), 16 + 8 * (from.id % 16) + side};
      if (dt >= 0) b[m++] = to;
    }
    n = m;
    std::copy(b.begin(), b.begin() + m, a.begin());
  }
  std::copy(a.begin(), a.begin() + n, out.begin());
  return n;
}

// Where more than four clipped points all touch (a face resting on a face), four points on the
// overlap's sides in their place, as a hull's face has its quad (hull.h): along the rays from the
// overlap's centre to +-a u +- b v, with u along the reference face's first side (fixed in its body),
// v = normal x u, and a, b the overlap's spread along them. Four of its corners could leave a side
// of it unsupported near its centre, and a stack leans there. A point between two clipped points
// lies on the incident face: its place (and separation) in proportion. Returns the new count.
int boundary_quad(const Feature& reference, const Vec3& on_plane, Real margin, std::array<Clipped, 32>& clipped, int count) {
  if (count <= 4) return count;
  const Vec3& n = reference.face_normal;
  for (int i = 0; i < count; ++i)
    if (n.dot(clipped[i].x - on_plane) > margin) return count;
  Vec3 u = reference.points[1] - reference.points[0];
  u = (u - n * n.dot(u)).normalized();
  const Vec3 v = n.cross(u);
  std::array<Eigen::Matrix<Real, 2, 1>, 32> p;
  for (int i = 0; i < count; ++i) p[i] = {u.dot(clipped[i].x - on_plane), v.dot(clipped[i].x - on_plane)};
  // The overlap's area, centre and spread, by triangles from its first point.
  Real area = 0;
  Eigen::Matrix<Real, 2, 1> first = Eigen::Matrix<Real, 2, 1>::Zero(), second = Eigen::Matrix<Real, 2, 1>::Zero();
  for (int i = 1; i + 1 < count; ++i) {
    const auto b = p[i] - p[0], c = p[i + 1] - p[0];
    const Real piece = (b.x() * c.y() - b.y() * c.x()) / 2;
    const auto sum = b + c;
    area += piece;
    first += piece * sum / 3;
    second += piece / 12 * (b.cwiseAbs2() + c.cwiseAbs2() + sum.cwiseAbs2());
  }
  if (!(std::abs(area) > Real(1e-12))) return count;
  const Eigen::Matrix<Real, 2, 1> centre = p[0] + first / area;
  const Eigen::Matrix<Real, 2, 1> spread = (second / area - (first / area).cwiseAbs2()).cwiseMax(Real(0)).cwiseSqrt();
  std::array<Clipped, 32> quad;
  const Real su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};
  for (int q = 0; q < 4; ++q) {
    const Eigen::Matrix<Real, 2, 1> d(su[q] * spread.x(), sv[q] * spread.y());
    // The nearest side the ray leaves by: centre + d t = p_i + (p_j - p_i) s, 0 <= s <= 1, t > 0.
    Real best_t = INFINITY;
    for (int i = 0; i < count; ++i) {
      const int j = (i + 1) % count;
      const auto e = p[j] - p[i], w = p[i] - centre;
      const Real det = d.x() * -e.y() + e.x() * d.y();  // of [d, -e]
      if (std::abs(det) < Real(1e-18)) continue;
      const Real t = (w.x() * -e.y() + e.x() * w.y()) / det, s = (d.x() * w.y() - d.y() * w.x()) / det;
      if (t > 0 && s >= 0 && s <= 1 && t < best_t) {
        best_t = t;
        quad[q] = {clipped[i].x + (clipped[j].x - clipped[i].x) * s, 200 + q};
      }
    }
    if (!std::isfinite(best_t)) return count;
  }
  std::copy(quad.begin(), quad.begin() + 4, clipped.begin());
  return 4;
}

}  // namespace

int collide_convex(const Body& a, int ia, const Body& b, int ib, Real margin, std::vector<Contact>& out) {
  const Mat3 rotation_a = a.orientation.toRotationMatrix(), rotation_b = b.orientation.toRotationMatrix();
  const Placed pa{&a.shape, a.position, rotation_a, margin / 2}, pb{&b.shape, b.position, rotation_b, margin / 2};
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd_support;
  ccd.support2 = ccd_support;
  ccd.center1 = ccd_centre;
  ccd.center2 = ccd_centre;
  ccd.max_iterations = 100;
  ccd.epa_tolerance = 1e-7;
  // The separation along a candidate normal n (A leaving B along it): A's nearest reach along -n
  // less B's farthest along n; the true separation is the largest over every n. EPA's and MPR's
  // directions are candidates (libccd's EPA now and then answers nonsense near a touching flat
  // face), and so are the faces' normals, which win where a face rests on the other.
  auto separation_along = [&](const Vec3& n) {
    return (a.position + rotation_a * local_support(a.shape, rotation_a.transpose() * -n)).dot(n) -
           (b.position + rotation_b * local_support(b.shape, rotation_b.transpose() * n)).dot(n);
  };
  Vec3 normal = Vec3::Zero();
  Real separation = -INFINITY;
  Vec3 epa_point = Vec3::Zero();
  auto consider = [&](const Vec3& n) {
    if (!(n.squaredNorm() > Real(0.5)) || !n.allFinite()) return;
    const Real s = separation_along(n);
    if (s > separation) separation = s, normal = n;
  };
  ccd_real_t depth;
  ccd_vec3_t direction, position;
  // libccd moves B by depth along `direction` to part them: A leaves B the other way.
  if (ccdGJKPenetration(&pa, &pb, &ccd, &depth, &direction, &position) == 0) {
    consider(-Vec3(ccdVec3X(&direction), ccdVec3Y(&direction), ccdVec3Z(&direction)));
    epa_point = Vec3(ccdVec3X(&position), ccdVec3Y(&position), ccdVec3Z(&position));
  } else {
    return 0;  // apart by more than the margin
  }
  if (ccdMPRPenetration(&pa, &pb, &ccd, &depth, &direction, &position) == 0) {
    const Vec3 before = normal;
    consider(-Vec3(ccdVec3X(&direction), ccdVec3Y(&direction), ccdVec3Z(&direction)));
    if (normal != before) epa_point = Vec3(ccdVec3X(&position), ccdVec3Y(&position), ccdVec3Z(&position));
  }
  for (int side = 0; side < 2; ++side) {  // the faces' normals: a box's three axes, a cylinder's, a hull's
    const Body& body = side == 0 ? a : b;
    const Mat3& rotation = side == 0 ? rotation_a : rotation_b;
    if (body.shape.type == ShapeType::box)
      for (int k = 0; k < 3; ++k) consider(rotation.col(k)), consider(-rotation.col(k));
    if (body.shape.type == ShapeType::cylinder) consider(rotation.col(1)), consider(-rotation.col(1));
    if (body.shape.type == ShapeType::hull)  // A leaves B against A's face's normal, along B's
      for (const HullFace& face : body.shape.hull()->faces) consider(rotation * face.normal * (side == 0 ? -1 : 1));
  }
  if (separation > margin) return 0;
  const Real epa_separation = separation;

  const Feature fa = supporting_feature(a, rotation_a, -normal), fb = supporting_feature(b, rotation_b, normal);
  const size_t first = out.size();
  auto add = [&](const Vec3& on_a, const Vec3& on_b, const Vec3& n, uint32_t id) {
    const Real gap = n.dot(on_a - on_b);
    if (gap <= margin) out.push_back({ia, ib, (on_a + on_b) / 2, n, gap, id});
  };
  // The reference face: A's or B's, the one whose normal is nearer the pair's.
  const Real align_a = fa.face ? -fa.face_normal.dot(normal) : -1, align_b = fb.face ? fb.face_normal.dot(normal) : -1;
  if (std::max(align_a, align_b) >= kFaceCos) {
    const int reference = align_b >= align_a ? 1 : 0;
    const Feature& face = reference == 1 ? fb : fa;
    const Vec3 n = reference == 1 ? face.face_normal : Vec3(-face.face_normal);
    // The other's feature again, along the face's normal.
    const Feature other = reference == 1 ? supporting_feature(a, rotation_a, -n) : supporting_feature(b, rotation_b, n);
    std::array<Clipped, 32> clipped;
    int count = clip_to_face(face, other, clipped);
    const Vec3& on_plane = face.points[0];
    count = boundary_quad(face, on_plane, margin, clipped, count);
    for (int i = 0; i < count; ++i) {
      const Vec3& x = clipped[i].x;
      const Vec3 projected = x - face.face_normal * face.face_normal.dot(x - on_plane);
      const bool round = other.round;
      const uint32_t id = feature::on_face(reference, clipped[i].id, reference == 1 && round, reference == 0 && round);
      if (reference == 1) add(x, projected, n, id);
      else add(projected, x, n, id);
    }
  } else if (fa.cored && fb.cored) {
    // Two cores grown round (capsules, cylinders' sides): along the line between their closest
    // points; two lines side by side touch at both ends of their overlap.
    Vec3 ca, cb;
    closest_points(fa.core[0], fa.core[1], fb.core[0], fb.core[1], ca, cb);
    const Vec3 da = fa.core[1] - fa.core[0], db = fb.core[1] - fb.core[0];
    const bool lines = fa.count == 2 && fb.count == 2;
    const bool side_by_side = lines && std::abs(da.normalized().dot(db.normalized())) >= kParallelCos;
    Vec3 n = ca - cb;
    if (side_by_side) n -= da * (da.dot(n) / da.squaredNorm());
    if (n.norm() > Real(1e-9)) normal = n.normalized();
    if (side_by_side) {
      const Vec3 unit = da.normalized();
      const Real b0 = unit.dot(fb.core[0] - fa.core[0]), b1 = unit.dot(fb.core[1] - fa.core[0]);
      const Real lo = std::max(Real(0), std::min(b0, b1)), hi = std::min(da.norm(), std::max(b0, b1));
      for (int end = 0; end < 2 && lo <= hi; ++end) {
        const Real t = end == 0 ? lo : hi;
        const Vec3 core_a = fa.core[0] + unit * t, core_b = fb.core[0] + db * ((t - b0) / (b1 - b0));
        add(core_a - fa.radius * normal, core_b + fb.radius * normal, normal, feature::round_point(end, true, true));
      }
    } else {
      add(ca - fa.radius * normal, cb + fb.radius * normal, normal, feature::round_point(0, true, true));
    }
  }
  if (out.size() == first) {
    if (epa_separation > margin) return 0;
    // libccd's point, where it is within reach of both shapes (near a touching face it can lie
    // far from either: a lever arm of metres).
    for (const Body* body : {&a, &b})
      if (!((epa_point - body->position).norm() <= bounding_radius(body->shape) + margin)) return 0;
    out.push_back({ia, ib, epa_point, normal, epa_separation, feature::round_point(0, fa.round, fb.round)});
    return 1;
  }
  Vec3 t1, t2;
  tangent_basis(out[first].normal, t1, t2);
  return reduce_manifold(out, first, out[first].normal, a.position, search_direction(t1, t2));
}

}  // namespace impulse::physics
