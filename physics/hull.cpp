#include "physics/hull.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace impulse::physics {

namespace {

// qhull's state, freed whatever happens.
struct Qhull {
  qhT qh;
  explicit Qhull(FILE* errors) { qh_zero(&qh, errors); }
  ~Qhull() {
    int long_left = 0, total_left = 0;
    qh_freeqhull(&qh, !qh_ALL);
    qh_memfreeshort(&qh, &long_left, &total_left);
  }
  Qhull(const Qhull&) = delete;
  Qhull& operator=(const Qhull&) = delete;
};

// Where qhull writes what went wrong: a buffer, not the terminal.
struct ErrorStream {
  char* text = nullptr;
  size_t size = 0;
  FILE* file = open_memstream(&text, &size);
  ~ErrorStream() {
    if (file) std::fclose(file);
    std::free(text);
  }
  std::string read() {
    if (!file) return {};
    std::fflush(file);
    return std::string(text, size);
  }
};

std::string show(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "[%g, %g, %g]", p.x(), p.y(), p.z());
  return text;
}

// Whether the points span a solid, with the reason they do not in words.
void require_solid(std::span<const Vec3> points) {
  if (points.size() < 4)
    throw std::invalid_argument("a hull needs at least 4 points not in one plane, got " + std::to_string(points.size()));
  for (const Vec3& p : points)
    if (!is_finite(p)) throw std::invalid_argument("a hull's points must be finite numbers, got " + show(p));
  // The largest tetrahedron found greedily: a point, the farthest from it, the farthest from their
  // line, the farthest from their plane.
  auto farthest = [&](auto distance) {
    size_t best = 0;
    for (size_t i = 1; i < points.size(); ++i)
      if (distance(points[i]) > distance(points[best])) best = i;
    return points[best];
  };
  const Vec3 a = points[0];
  const Vec3 b = farthest([&](const Vec3& p) { return (p - a).norm(); });
  const Real size = (b - a).norm();
  if (!(size > 0)) throw std::invalid_argument("a hull's points are all the same point " + show(a));
  const Vec3 line = (b - a) / size;
  const Vec3 c = farthest([&](const Vec3& p) { return (p - a - line * line.dot(p - a)).norm(); });
  const Vec3 across = (c - a).cross(line);
  if (across.norm() <= Real(1e-9) * size)
    throw std::invalid_argument("a hull's points all lie on one line, through " + show(a) + " and " + show(b));
  const Vec3 up = across.normalized();
  const Vec3 d = farthest([&](const Vec3& p) { return std::abs(up.dot(p - a)); });
  if (std::abs(up.dot(d - a)) <= Real(1e-9) * size)
    throw std::invalid_argument("a hull's points all lie in one plane, through " + show(a) + ", " + show(b) + " and " + show(c) +
                                ": give at least one point off it");
}

// Volume, area and both tensors, from the faces split into triangles about each face's first corner
// and tetrahedra to `centre`:
//   a tetrahedron (centre, p, q, r), edges a, b, c from the centre: V = det[a b c] / 6,
//     its second moment about the centre V/20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c;
//   a triangle of area A, corners a, b, c from the centre: A/12 (a a^T + b b^T + c c^T + s s^T).
// The inertia of a body whose second moment about its centre of mass is C: trace(C) 1 - C.
struct Moments {
  Real volume = 0, area = 0;
  Vec3 first_volume = Vec3::Zero(), first_area = Vec3::Zero();  // integrals of x, from `centre`
  Mat3 second_volume = Mat3::Zero(), second_area = Mat3::Zero();
};

Moments moments_about(const Hull& hull, const Vec3& centre) {
  Moments m;
  for (const HullFace& face : hull.faces) {
    const Vec3 a = hull.corners[hull.corner_of(face, 0)] - centre;
    for (int k = 1; k + 1 < face.count; ++k) {
      const Vec3 b = hull.corners[hull.corner_of(face, k)] - centre;
      const Vec3 c = hull.corners[hull.corner_of(face, k + 1)] - centre;
      const Vec3 s = a + b + c;
      const Mat3 spread = a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose();
      const Real volume = a.dot(b.cross(c)) / 6;
      const Real area = (b - a).cross(c - a).norm() / 2;
      m.volume += volume;
      m.first_volume += volume * s / 4;
      m.second_volume += volume / 20 * spread;
      m.area += area;
      m.first_area += area * s / 3;
      m.second_area += area / 12 * spread;
    }
  }
  return m;
}

Mat3 inertia_of(const Mat3& second) { return Mat3::Identity() * second.trace() - second; }

// A face's quad (HullFace::quad): its area's centre c and second moments in its plane, the
// principal axes u, v = n x u, and the sides' crossings of the rays from c along +-a u +- b v (a, b:
// the spreads along u and v).
void with_quad(const Hull& hull, HullFace& face) {
  const Vec3& n = face.normal;
  const Vec3 p0 = hull.corners[hull.corner_of(face, 0)];
  Real area = 0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  for (int k = 1; k + 1 < face.count; ++k) {
    const Vec3 b = hull.corners[hull.corner_of(face, k)] - p0, c = hull.corners[hull.corner_of(face, k + 1)] - p0;
    const Real piece = b.cross(c).dot(n) / 2;
    const Vec3 s = b + c;
    area += piece;
    first += piece * s / 3;
    second += piece / 12 * (b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  const Vec3 centre = p0 + first / area;
  const Mat3 spread = (second - first * first.transpose() / area) / area;  // about the centre, per unit area
  Vec3 u = std::abs(n.x()) < Real(0.9) ? Vec3::UnitX() : Vec3::UnitY();
  u = (u - n * n.dot(u)).normalized();
  Vec3 v = n.cross(u);
  const Real uu = u.dot(spread * u), vv = v.dot(spread * v), uv = u.dot(spread * v);
  const Real angle = std::atan2(2 * uv, uu - vv) / 2;  // the principal axes in the plane
  const Vec3 pu = std::cos(angle) * u + std::sin(angle) * v;
  u = pu;
  v = n.cross(u);
  const Real a = std::sqrt(std::max(u.dot(spread * u), Real(0))), b = std::sqrt(std::max(v.dot(spread * v), Real(0)));
  const Real su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};
  for (int q = 0; q < 4; ++q) {
    const Vec3 d = su[q] * a * u + sv[q] * b * v;
    // The nearest side the ray crosses: t with (x_k + (x_k+1 - x_k) s) = centre + d t.
    Real t = INFINITY;
    for (int k = 0; k < face.count; ++k) {
      const Vec3 x0 = hull.corners[hull.corner_of(face, k)], x1 = hull.corners[hull.corner_of(face, (k + 1) % face.count)];
      const Vec3 outward = (x1 - x0).cross(n);  // the side's outward normal in the plane
      const Real closing = outward.dot(d);
      if (closing > 0) t = std::min(t, outward.dot(x0 - centre) / closing);
    }
    face.quad[q] = centre + d * t;
  }
}

Vec3 corners_mean(const Hull& hull) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : hull.corners) mean += p;
  return mean / Real(hull.corners.size());
}

// Volume, area and both tensors about the origin: the moments about the corners' mean (near the
// centre, for rounding), moved by parallel axes.
void with_mass(Hull& hull) {
  const Vec3 mean = corners_mean(hull);
  const Moments m = moments_about(hull, mean);
  hull.volume = m.volume;
  hull.area = m.area;
  auto about_origin = [&](const Mat3& second, const Vec3& first, Real amount) {
    return Mat3(second + mean * first.transpose() + first * mean.transpose() + amount * mean * mean.transpose());
  };
  hull.unit_inertia = inertia_of(about_origin(m.second_volume, m.first_volume, m.volume)) / m.volume;
  hull.unit_shell_inertia = inertia_of(about_origin(m.second_area, m.first_area, m.area)) / m.area;
}

// The same hull seen from a frame at `origin` turned by `rotation`: x_new = rotation^T (x - origin).
Hull moved(const Hull& hull, const Vec3& origin, const Mat3& rotation) {
  Hull out = hull;
  for (Vec3& p : out.corners) p = rotation.transpose() * (p - origin);
  for (HullFace& face : out.faces) {
    face.normal = rotation.transpose() * face.normal;
    face.offset = face.normal.dot(out.corners[out.corner_of(face, 0)]);
    for (Vec3& q : face.quad) q = rotation.transpose() * (q - origin);
  }
  with_mass(out);
  return out;
}

}  // namespace

Hull convex_hull(std::span<const Vec3> points) {
  require_solid(points);
  std::vector<coordT> coordinates;
  coordinates.reserve(points.size() * 3);
  for (const Vec3& p : points) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  ErrorStream errors;
  Qhull q(errors.file);
  qhT* qh = &q.qh;
  char command[] = "qhull";  // default merging in 3-d: coplanar facets become one face
  if (qh_new_qhull(qh, 3, int(points.size()), coordinates.data(), False, command, nullptr, errors.file) != 0)
    throw std::invalid_argument("qhull could not build the hull of these points: " + errors.read());

  Hull hull;
  std::vector<int> index_of(points.size(), -1);  // a point's index among the corners
  facetT* facet;
  FORALLfacets {
    HullFace face;
    face.normal = Vec3(facet->normal[0], facet->normal[1], facet->normal[2]);
    face.first = int(hull.face_corners.size());
    setT* ordered = qh_facet3vertex(qh, facet);
    vertexT *vertex, **vertexp;
    FOREACHvertex_(ordered) {
      const int point = qh_pointid(qh, vertex->point);
      if (index_of[point] < 0) index_of[point] = int(hull.corners.size()), hull.corners.push_back(points[point]);
      hull.face_corners.push_back(index_of[point]);
    }
    qh_settempfree(qh, &ordered);
    face.count = int(hull.face_corners.size()) - face.first;
    // Counter-clockwise seen from outside: the polygon's own normal (Newell's) along the outward one.
    Vec3 newell = Vec3::Zero();
    for (int k = 0; k < face.count; ++k)
      newell += hull.corners[hull.corner_of(face, k)].cross(hull.corners[hull.corner_of(face, (k + 1) % face.count)]);
    if (newell.dot(face.normal) < 0) std::reverse(hull.face_corners.begin() + face.first, hull.face_corners.end());
    face.offset = face.normal.dot(hull.corners[hull.corner_of(face, 0)]);
    with_quad(hull, face);
    hull.faces.push_back(face);
  }
  with_mass(hull);
  return hull;
}

PlacedHull place_hull(std::span<const Vec3> points, bool shell) {
  const Hull given = convex_hull(points);
  const Vec3 mean = corners_mean(given);
  const Moments m = moments_about(given, mean);
  const Vec3 centre = mean + (shell ? Vec3(m.first_area / m.area) : Vec3(m.first_volume / m.volume));
  const Hull centred = moved(given, centre, Mat3::Identity());
  const Mat3 inertia = shell ? centred.unit_shell_inertia : centred.unit_inertia;
  // The principal axes; where the tensor is diagonal already (to rounding), the points' own axes.
  Mat3 axes = Mat3::Identity();
  const Real off = std::max({std::abs(inertia(0, 1)), std::abs(inertia(0, 2)), std::abs(inertia(1, 2))});
  if (off > Real(1e-12) * inertia.trace()) {
    Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia);
    const Mat3 vectors = solver.eigenvectors();
    // The order and signs that keep each axis nearest a given one (the most of the diagonal), then
    // right-handed.
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    Real best = -1;
    for (const auto& order : orders) {
      Mat3 candidate;
      for (int k = 0; k < 3; ++k) candidate.col(k) = vectors.col(order[k]);
      if (candidate.diagonal().cwiseAbs().sum() > best) best = candidate.diagonal().cwiseAbs().sum(), axes = candidate;
    }
    for (int k = 0; k < 3; ++k)
      if (axes(k, k) < 0) axes.col(k) = -axes.col(k);
    if (axes.determinant() < 0) {
      Eigen::Index weakest;
      axes.diagonal().cwiseAbs().minCoeff(&weakest);
      axes.col(weakest) = -axes.col(weakest);
    }
  }
  PlacedHull placed;
  placed.hull = std::make_shared<const Hull>(moved(centred, Vec3::Zero(), axes));
  placed.centre = centre;
  placed.frame = Quat(axes).normalized();
  return placed;
}

std::vector<Vec3> wedge_points(const Vec3& size) {
  const Vec3 h = size / 2;
  return {{-h.x(), -h.y(), -h.z()}, {h.x(), -h.y(), -h.z()}, {-h.x(), h.y(), -h.z()},
          {-h.x(), -h.y(), h.z()},  {h.x(), -h.y(), h.z()},  {-h.x(), h.y(), h.z()}};
}

std::vector<Vec3> tetrahedron_points(Real edge) {
  // One face down in the plane y = -height/4, its apex at 3/4 of the height above the centre.
  const Real height = edge * std::sqrt(Real(2) / 3), r = edge / std::sqrt(Real(3));
  std::vector<Vec3> points{{0, Real(3) / 4 * height, 0}};
  for (int k = 0; k < 3; ++k) {
    const Real angle = 2 * std::numbers::pi * k / 3;
    points.push_back({r * std::cos(angle), -height / 4, r * std::sin(angle)});
  }
  return points;
}

std::vector<Vec3> prism_points(int sides, Real radius, Real height) {
  std::vector<Vec3> points;
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k < sides; ++k) {
      const Real angle = 2 * std::numbers::pi * k / sides;
      points.push_back({radius * std::cos(angle), end == 0 ? -height / 2 : height / 2, radius * std::sin(angle)});
    }
  return points;
}

}  // namespace impulse::physics
