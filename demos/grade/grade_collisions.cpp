// The grade's collisions, in zero gravity: head on (eq. 5 and 7), off centre (eq. 11-14) and
// oblique (Coulomb). Each pair first overlaps by 1 mm at the start of step 10, so that a position
// correction beyond a slop of a few millimetres, or line 85's 1.5 x penetration (0.0015 N s here),
// hardly shows: the cases judge the impulse itself.
#include "demos/grade/grade_case.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace impulse::workshop {

namespace {

using physics::Vec3;

constexpr int kHitStep = 10;            // the step at whose start the pair overlaps by kFirstDepth
constexpr double kFirstDepth = 0.001;   // m
constexpr double kSpeedShare = 0.02;    // of the closing speed: how near eq. 5's parting speed must be
constexpr double kMomentumShare = 1e-3; // of the momenta's scale: how well momentum must be kept

Vec3 momentum(const Run& run, size_t step) {
  Vec3 total = Vec3::Zero();
  for (const physics::Body& body : run.states[step]) total += body.mass * body.velocity;
  return total;
}

// Angular momentum about a fixed point (eq. 12: what an impulse pair at that point cannot change).
Vec3 angular_momentum(const Run& run, size_t step, const Vec3& about) {
  Vec3 total = Vec3::Zero();
  for (const physics::Body& body : run.states[step])
    if (!body.is_static()) total += (body.position - about).cross(body.mass * body.velocity) + body.inertia_world() * body.angular_velocity;
  return total;
}

double deepest(const Run& run) {
  double depth = 0;
  for (const auto& step : run.contacts)
    for (const physics::ContactRecord& contact : step) depth = std::max(depth, double(contact.penetration));
  return depth;
}

// The hint for a parting speed that is not eq. 5's, from what the pair did.
std::string parting_hint(double parting, double expected, double closing, double depth, double e) {
  if (parting < expected - kSpeedShare * closing) {
    if (depth > 0.01)
      return format("they kept closing after they touched (%.1f cm deep): J is too small. With eq. 8 and 13 as printed, "
                    "-(1 - e), the impulse is (1 - e)/(1 + e) of the one that parts them, and they go on closing at e of "
                    "their speed; the listing's line 81 has -(1 + e)", 100 * depth);
    if (e > 0 && parting < 0.5 * expected)
      return format("they part at %.2f m/s, far slower than e = %g gives: is e the pair's, c0.m_restitution? (the listing "
                    "hard-codes float e = 0.0f, line 71)", parting, e);
    return "eq. 5: the normal speed after is -e times the speed before; eq. 8 and 13 with -(1 + e) give the J that does it";
  }
  return "they part faster than e allows: something more is added to J (line 85's 1.5 x penetration, or a position "
         "correction that acts before the depth passes a slop of a few millimetres?)";
}

const char* kMomentumHint =
    "the impulses on c0 and c1 must be equal and opposite (eq. 7 and 9: + J n on c0, - J n on c1; the printed eq. 7 "
    "adds to both; the listing subtracts for c1, lines 91-92)";

// Head on along x: a (m_a) at +2 m/s, b (m_b) at -1 m/s, both spheres of 0.25 m.
GradeCaseSpec head_on(const std::string& masses, double mass_b, double e) {
  const std::string e_text = e == 0 ? "0" : e == 1 ? "1" : format("%g", e);
  GradeCaseSpec spec = grade_case_spec(
    "head_on_" + masses + "_e" + e_text, "head on, " + masses + " masses, e = " + e_text,
    "eq. 5 and 7: they part at e times the speed they met; momentum kept",
    {1.0, false, {0.0f, 0.6f, 3.2f}, {0.0f, 0.0f, 0.0f}}, [=](demos::Scene& scene) {
    const double gap = 3.0 * kHitStep / 60 - kFirstDepth;  // closing at 3 m/s, 5 cm a step
    add_sphere(scene, "a", 0.25, 1.0, Vec3(-0.6, 0, 0), Vec3(2, 0, 0), e, 0.3);
    add_sphere(scene, "b", 0.25, mass_b, Vec3(-0.6 + 0.5 + gap, 0, 0), Vec3(-1, 0, 0), e, 0.3);
  });
  spec.judge = [=](const Run& run) {
    const size_t end = run.states.size() - 1;
    const double closing = 3, expected = e * closing;
    const double parting = run.body(end, "b").velocity.x() - run.body(end, "a").velocity.x();
    const Vec3 p0 = momentum(run, 0), p1 = momentum(run, end);
    const double scale = 2 * 1.0 + 1 * mass_b;
    Verdict verdict;
    verdict.expected = format("part at %.2f m/s; momentum %.2f kg m/s", expected, p0.x());
    verdict.measured = format("part at %.2f m/s; momentum %.2f kg m/s", parting, p1.x());
    const bool speed_right = std::abs(parting - expected) <= kSpeedShare * closing;
    const bool momentum_kept = (p1 - p0).norm() <= kMomentumShare * scale;
    verdict.passed = speed_right && momentum_kept;
    if (!momentum_kept)
      verdict.hint = format("momentum changed by %.3f kg m/s: ", (p1 - p0).norm()) + kMomentumHint;
    else if (!speed_right)
      verdict.hint = parting_hint(parting, expected, closing, deepest(run), e);
    return verdict;
  };
  return spec;
}

// The state just before the hit (the start of the step that first finds the pair touching) and
// just after the hit (the first step that no longer does), with the contact's point and normal
// (the normal pushes `a`).
struct Hit {
  int before = -1, after = -1;
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero();
};
Hit find_hit(const Run& run, const std::string& a, const std::string& b) {
  Hit hit;
  hit.before = run.first_touch(a, b);
  if (hit.before < 0) return hit;
  hit.after = run.first_apart(a, b, hit.before);
  for (const physics::ContactRecord& contact : run.contacts[hit.before])
    if (contact.penetration >= 0) {
      const bool a_first = contact.body_a == run.index_of(a);
      hit.point = contact.point;
      hit.normal = a_first ? contact.normal : Vec3(-contact.normal);
      break;
    }
  return hit;
}

// The pair just before and just after their hit; or nothing, and `verdict` says there was no hit
// and gives `hint`.
struct HitPair {
  Hit hit;
  const physics::Body *a0, *b0, *a1, *b1;
};
std::optional<HitPair> hit_pair(const Run& run, const std::string& a, const std::string& b, Verdict& verdict, const char* hint) {
  const Hit hit = find_hit(run, a, b);
  if (hit.before < 0 || hit.after < 0) {
    verdict.measured = hit.before < 0 ? "they never touched" : "they never parted";
    verdict.hint = hint;
    return std::nullopt;
  }
  return HitPair{hit, &run.body(hit.before, a), &run.body(hit.before, b), &run.body(hit.after, a), &run.body(hit.after, b)};
}

// The velocity of `body`'s material point at `point` (eq. 11, with the cross product).
Vec3 point_velocity(const physics::Body& body, const Vec3& point) {
  return body.velocity + body.angular_velocity.cross(point - body.position);
}

physics::Mat3 world_inverse_inertia(const physics::Body& body) {
  const physics::Mat3 turn = body.orientation.toRotationMatrix();
  return turn * body.inv_inertia_local * turn.transpose();
}

// Where the material point of `before` at `point` is in `after` (the same body, later).
Vec3 carried(const physics::Body& before, const physics::Body& after, const Vec3& point) {
  return after.position + after.orientation * (before.orientation.conjugate() * (point - before.position));
}

// A sphere (1 kg) at 3 m/s hits a tall box (2 kg) at rest 0.45 m above its centre; e = 0.5, no friction.
GradeCaseSpec off_centre() {
  GradeCaseSpec spec = grade_case_spec(
    "off_centre_spin", "off centre: the box must spin",
    "eq. 11-14: the contact points part at e of their speed; momentum and angular momentum about the hit kept",
    {0.8, false, {0.0f, 0.3f, 3.4f}, {0.0f, 0.2f, 0.0f}}, [=](demos::Scene& scene) {
    add_sphere(scene, "ball", 0.2, 1.0, Vec3(-0.4 - 3.0 * kHitStep / 60 + kFirstDepth, 0.45, 0), Vec3(3, 0, 0), 0.5, 0);
    add_box(scene, "box", Vec3(0.2, 0.6, 0.2), 2.0, Vec3::Zero(), Vec3::Zero(), 0.5, 0);
  });
  spec.judge = [](const Run& run) {
    Verdict verdict;
    const auto pair = hit_pair(run, "ball", "box", verdict, "the ball must bounce off the box: an impulse along the normal at the hit point (eq. 13)");
    if (!pair) return verdict;
    const Hit& hit = pair->hit;
    const physics::Body &ball0 = *pair->a0, &box0 = *pair->b0, &ball1 = *pair->a1, &box1 = *pair->b1;
    const Vec3& n = hit.normal;
    const double closing = -(point_velocity(ball0, hit.point) - point_velocity(box0, hit.point)).dot(n);
    // eq. 13 with 1 + e, no friction: J on the ball along n; eq. 14: the box turns by I^-1 (r x -J n).
    const Vec3 r_ball = hit.point - ball0.position, r_box = hit.point - box0.position;
    const physics::Mat3 inv_ball = world_inverse_inertia(ball0), inv_box = world_inverse_inertia(box0);
    const double k = ball0.inv_mass + box0.inv_mass + n.dot((inv_ball * r_ball.cross(n)).cross(r_ball) + (inv_box * r_box.cross(n)).cross(r_box));
    const double e = 0.5, impulse = (1 + e) * closing / k;
    const double spin_expected = (inv_box * r_box.cross(-impulse * n)).z();
    // After: the same material points (moved with their bodies since), and their parting speed.
    const double parting = (point_velocity(ball1, carried(ball0, ball1, hit.point)) - point_velocity(box1, carried(box0, box1, hit.point))).dot(n);
    const Vec3 l0 = angular_momentum(run, hit.before, hit.point), l1 = angular_momentum(run, hit.after, hit.point);
    const Vec3 p0 = momentum(run, hit.before), p1 = momentum(run, hit.after);
    const double spin = box1.angular_velocity.z();
    const double l_scale = ball0.mass * ball0.velocity.norm() * (ball0.position - hit.point).norm() + 1e-9;
    verdict.expected = format("box spins at %.3f rad/s; part at %.2f m/s; angular momentum about the hit kept", spin_expected, e * closing);
    verdict.measured = format("box spins at %.3f rad/s; part at %.2f m/s; angular momentum about the hit changed by %.4f kg m^2/s",
                              spin, parting, (l1 - l0).norm());
    const bool momentum_kept = (p1 - p0).norm() <= kMomentumShare * ball0.mass * ball0.velocity.norm();
    const bool angular_kept = (l1 - l0).norm() <= kMomentumShare * 10 * l_scale;
    const bool spins = std::abs(spin - spin_expected) <= 0.03 * std::abs(spin_expected);
    const bool parts = std::abs(parting - e * closing) <= kSpeedShare * closing;
    verdict.passed = momentum_kept && angular_kept && spins && parts;
    if (!momentum_kept)
      verdict.hint = kMomentumHint;
    else if (std::abs(spin) < 0.1 * std::abs(spin_expected))
      verdict.hint = "the box did not turn: eq. 14, w+ = w- + I^-1 (r x J n), in the world's frame (m_worldInvInertia; the "
                     "listing's lines 88 and 92)";
    else if (!angular_kept)
      verdict.hint = "angular momentum about the hit changed: each body turns by its own I^-1 (r x its impulse), c1's with "
                     "- J n (eq. 12 as printed adds for body b; the listing subtracts, line 92)";
    else if (!parts && parting < 0.5 * e * closing)
      verdict.hint = parting_hint(parting, e * closing, closing, deepest(run), e);
    else
      verdict.hint = "eq. 13: the denominator needs both bodies' angular terms [(I^-1 (r x n)) x r] . n, and eq. 11 the "
                     "velocity of the point, v + w x r (not v - w r)";
    return verdict;
  };
  return spec;
}

// A sphere (1 kg) at 2 m/s glances off one of 2 kg at rest, 30 degrees off centre; e = 0.8, mu = 0.05
// (so little that friction cannot stop the sliding at the contact: its clamp decides).
GradeCaseSpec oblique() {
  GradeCaseSpec spec = grade_case_spec(
    "oblique", "oblique hit, mu = 0.05",
    "eq. 5 along the normal, and Coulomb across it: |Jt| <= mu Jn; momentum kept",
    {0.8, false, {0.0f, 0.3f, 3.4f}, {0.0f, 0.1f, 0.0f}}, [=](demos::Scene& scene) {
    const double across = 0.25, centres = 0.5 - kFirstDepth;  // 1 mm deep at the start of step 10
    const double along = std::sqrt(centres * centres - across * across) + 2.0 * kHitStep / 60;
    add_sphere(scene, "a", 0.25, 1.0, Vec3(-along, across, 0), Vec3(2, 0, 0), 0.8, 0.05);
    add_sphere(scene, "b", 0.25, 2.0, Vec3::Zero(), Vec3::Zero(), 0.8, 0.05);
  });
  spec.judge = [](const Run& run) {
    Verdict verdict;
    const auto pair = hit_pair(run, "a", "b", verdict, "the spheres must bounce apart: an impulse along the normal at the hit point (eq. 13)");
    if (!pair) return verdict;
    const physics::Body &a0 = *pair->a0, &b0 = *pair->b0, &a1 = *pair->a1, &b1 = *pair->b1;
    const Vec3& n = pair->hit.normal;
    const double closing = -(a0.velocity - b0.velocity).dot(n), parting = (a1.velocity - b1.velocity).dot(n);
    const Vec3 given = a0.mass * (a1.velocity - a0.velocity);  // the impulse on a (eq. 2)
    const double jn = given.dot(n), jt = (given - jn * n).norm(), mu = 0.05, e = 0.8;
    const Vec3 p0 = momentum(run, pair->hit.before), p1 = momentum(run, pair->hit.after);
    verdict.expected = format("part at %.2f m/s along n; |Jt| <= %.3f N s (mu Jn)", e * closing, mu * jn);
    verdict.measured = format("part at %.2f m/s along n; |Jt| = %.3f N s", parting, jt);
    const bool momentum_kept = (p1 - p0).norm() <= kMomentumShare * a0.mass * a0.velocity.norm();
    const bool parts = std::abs(parting - e * closing) <= kSpeedShare * closing;
    const bool coulomb = jt <= mu * std::max(jn, 0.0) * 1.02 + 1e-4;
    verdict.passed = momentum_kept && parts && coulomb;
    if (!momentum_kept)
      verdict.hint = kMomentumHint;
    else if (!coulomb)
      verdict.hint = "friction's impulse is more than mu Jn: clamp jt to -mu jn .. mu jn with mu = c0.m_friction (Coulomb; the "
                     "listing's line 119 says it does not)";
    else if (!parts)
      verdict.hint = parting_hint(parting, e * closing, closing, deepest(run), e);
    return verdict;
  };
  return spec;
}

}  // namespace

std::vector<GradeCaseSpec> collision_cases() {
  std::vector<GradeCaseSpec> cases;
  for (const auto& [masses, mass_b] : {std::pair<const char*, double>{"equal", 1.0}, {"unequal", 3.0}})
    for (const double e : {0.0, 0.7, 1.0}) cases.push_back(head_on(masses, mass_b, e));
  cases.push_back(off_centre());
  cases.push_back(oblique());
  return cases;
}

}  // namespace impulse::workshop
