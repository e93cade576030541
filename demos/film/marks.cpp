#include "demos/film/marks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

namespace impulse::demos {
namespace {

// The largest 1, 2 or 5 x 10^k not above `x` (> 0).
double round_down(double x) {
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= x * (1 + 1e-9)) return m * decade;
  return decade;
}

constexpr double kLongestArrow = 1.5;  // m, the largest value's arrow

double auto_scale(double chosen, double largest) {
  if (chosen > 0) return chosen;
  return largest > 1e-9 ? round_down(kLongestArrow / largest) : 1.0;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// "normal impulse, = 50 N·s": a round value whose arrow is 40..110 pixels at the target.
render::LegendEntry scaled_entry(const std::string& what, const char* unit, render::Colour colour,
                                 double metres_per_unit, double pixels_per_metre) {
  const double pixels_per_unit = metres_per_unit * pixels_per_metre;
  if (!(pixels_per_unit > 0)) return {colour, what, 0.0f, false};
  const double value = round_down(110.0 / pixels_per_unit);
  return {colour, what + ": " + number(value) + " " + unit, float(value * pixels_per_unit), false};
}

}  // namespace

double body_size(const physics::Shape& shape) {
  switch (shape.type) {
    case physics::ShapeType::sphere: return shape.radius;
    case physics::ShapeType::box: return shape.half_extents.minCoeff();
    case physics::ShapeType::capsule: return shape.radius;
    case physics::ShapeType::cylinder: return std::min(shape.radius, shape.half_height);
    case physics::ShapeType::hull: return physics::thinnest_half_size(shape);
    case physics::ShapeType::mesh:
    case physics::ShapeType::plane: return INFINITY;
  }
  return INFINITY;
}

ArrowScales arrow_scales(const Scene& scene, const TakeSummary& summary) {
  const DrawOptions& draw = scene.draw;
  double smallest = 0.4;  // m, when nothing moves
  bool found = false;
  for (const physics::BodyDef& body : scene.bodies) {
    if (body.is_static || body.shape.type == physics::ShapeType::plane) continue;
    smallest = found ? std::min(smallest, body_size(body.shape)) : body_size(body.shape);
    found = true;
  }
  const double normal = draw.normal_length > 0 ? draw.normal_length : std::clamp(1.5 * smallest, 0.05, 1.0);
  const double fitted = summary.impulse_to_fit > 0 ? summary.impulse_to_fit : summary.largest_impulse;
  return {auto_scale(draw.impulse_scale, fitted), draw.impulse_scale > 0 ? INFINITY : 1.5 * kLongestArrow,
          auto_scale(draw.velocity_scale, summary.largest_speed), normal};
}

double impulse_to_fit(const std::vector<ImpulsePeak>& all) {
  constexpr double kMoment = 0.25;  // s around the largest
  constexpr double kOutweighs = 4;
  std::vector<ImpulsePeak> peaks;
  std::copy_if(all.begin(), all.end(), std::back_inserter(peaks), [](const ImpulsePeak& peak) { return peak.impact; });
  if (peaks.empty()) peaks = all;
  if (peaks.empty()) return 0;
  const ImpulsePeak largest = *std::max_element(peaks.begin(), peaks.end(), [](const ImpulsePeak& a, const ImpulsePeak& b) {
    return a.impulse < b.impulse;
  });
  double others = 0;
  for (const ImpulsePeak& peak : peaks)
    if (std::abs(peak.time - largest.time) > kMoment) others = std::max(others, peak.impulse);
  return others > 0 && largest.impulse > kOutweighs * others ? others : largest.impulse;
}

std::vector<physics::ContactRecord> marked_contacts(const std::vector<physics::ContactRecord>& contacts, int max_pairs) {
  std::vector<physics::ContactRecord> pairs;  // one per pair, in the order pairs first appear
  std::vector<int> points;
  for (const physics::ContactRecord& contact : contacts) {
    auto same = [&](const physics::ContactRecord& p) { return p.body_a == contact.body_a && p.body_b == contact.body_b; };
    const auto found = std::find_if(pairs.begin(), pairs.end(), same);
    if (found == pairs.end()) {
      physics::ContactRecord& pair = pairs.emplace_back(contact);
      pair.point = contact.point * contact.normal_impulse;
      points.push_back(1);
      continue;
    }
    const size_t k = size_t(found - pairs.begin());
    // Sums for now: the point weighted by impulse, the normal; divided below.
    found->point += contact.point * contact.normal_impulse;
    found->normal += contact.normal;
    found->penetration = std::max(found->penetration, contact.penetration);
    found->normal_impulse += contact.normal_impulse;
    found->tangent_impulse += contact.tangent_impulse;
    ++points[k];
  }
  if (max_pairs <= 0 || int(pairs.size()) <= max_pairs) return contacts;
  for (size_t k = 0; k < pairs.size(); ++k) {
    physics::ContactRecord& pair = pairs[k];
    if (pair.normal_impulse > 0) {
      pair.point /= pair.normal_impulse;
    } else {  // no impulse to weigh by: the points' mean
      pair.point.setZero();
      for (const physics::ContactRecord& c : contacts)
        if (c.body_a == pair.body_a && c.body_b == pair.body_b) pair.point += c.point / points[k];
    }
    pair.normal.normalize();
  }
  std::vector<int> order(pairs.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = int(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pairs[a].normal_impulse > pairs[b].normal_impulse; });
  order.resize(size_t(max_pairs));
  std::sort(order.begin(), order.end());
  std::vector<physics::ContactRecord> marked;
  for (const int k : order) marked.push_back(pairs[k]);
  return marked;
}

render::Vec3f cut_to(const render::Vec3f& arrow, double longest) {
  const float length = arrow.norm();
  return length > longest ? arrow * float(longest / length) : arrow;
}

std::vector<render::LegendEntry> legend(const DrawOptions& draw, const ArrowScales& scales, const render::CameraView& camera,
                                        const render::Vec3f& target, bool someone_sleeps) {
  const double pixels_per_metre = camera.pixels_per_metre(target);
  std::vector<render::LegendEntry> entries;
  if (draw.contact_points) entries.push_back({mark_colour::contact_point, "contact point", 0.0f, true});
  if (draw.contact_normals) entries.push_back({mark_colour::contact_normal, "contact normal", 0.0f, false});
  if (draw.impulses)
    entries.push_back(scaled_entry("normal impulse", "N\u00b7s", mark_colour::normal_impulse, scales.impulse, pixels_per_metre));
  if (draw.friction)
    entries.push_back(scaled_entry("friction impulse", "N\u00b7s", mark_colour::friction_impulse, scales.impulse, pixels_per_metre));
  if (draw.velocities)
    entries.push_back(scaled_entry("velocity", "m/s", mark_colour::velocity, scales.velocity, pixels_per_metre));
  if (draw.sleeping && someone_sleeps) entries.push_back({mark_colour::asleep_swatch, "asleep (pale, hatched)", 0.0f, false, true});
  return entries;
}

}  // namespace impulse::demos
