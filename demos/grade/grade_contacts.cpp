// The grade's lasting contacts, under gravity: balls resting on the ground, a box sliding with and
// without friction, a ball bouncing with backspin, two boxes stacked. What listing 1's method can
// be asked: one impulse per contact per step in a fixed order leaves a box on four corners turning
// a little after each pass, and friction at the corners after the first turns that into sliding,
// so a box that has stopped creeps on at a few centimetres a second and a stack walks (ERRATA.md,
// "one pass per contact"); the engine's own listing page does the same. The cases hold the
// response to the laws that method can keep (Coulomb's stopping distance and time; a bounce that
// leaves rolling where mu Jn allows it; a stack that stands, upright, neither box sinking), and
// report the creep without counting it.
#include "demos/grade/grade_case.h"
#include "demos/grade/listing_code.h"

#include <algorithm>
#include <cmath>

namespace impulse::workshop {

namespace {

using physics::Vec3;

constexpr double kG = 9.81;

double tilt(const physics::Body& body) { return 2 * std::acos(std::min(1.0, std::abs(body.orientation.w()))); }
double speed(const physics::Body& body, double reach) { return body.velocity.norm() + body.angular_velocity.norm() * reach; }
double horizontal(const Vec3& v) { return std::hypot(v.x(), v.z()); }

const char* kTooWeak = "they sink: the position correction is too weak for 10 kg boxes (a larger beta, through eq. 13's denominator)";
const char* kBaumgarte = "jn += beta / TimeStep() * (penetration - slop) / normDiv";

// A push that does not grow with the mass it holds up; the listing's hack fix named where the
// student's file has it.
std::string mass_blind_hint(const Run& run, const std::string& what) {
  const int line = hack_fix_line(run.source);
  const std::string push = line > 0 ? format("your line %d, the listing's hack fix (its line 85, jn += 1.5 * penetration),", line)
                                    : std::string("a push of a length times a number added to jn");
  return what + ": " + push + " adds a length to an impulse, so it does not grow with the mass it holds up. Close the depth as a "
         "speed through eq. 13's denominator instead (Baumgarte: " + kBaumgarte + "), which holds any mass alike";
}

// The depth was never pushed back (it only grew): no position correction at all.
std::string never_corrected_hint(double depth) {
  return format("the penetration is never corrected: they sank %.1f cm and nothing pushed them back out. Each step's impulse "
                "stops the approach, but the depth that gravity's g dt opened stays, and grows step after step. Add a position "
                "correction through eq. 13's denominator (Baumgarte: %s)", 100 * depth, kBaumgarte);
}

// Whether `depth` (one value a step) grew and never shrank by more than a millimetre: nothing
// pushed back.
bool only_grew(const std::vector<double>& depth) {
  double deepest = 0;
  for (double d : depth) {
    if (d < deepest - 0.001) return false;
    deepest = std::max(deepest, d);
  }
  return true;
}

// Balls of 1 kg and 50 kg set down on the ground (e = 0.5), left to rest for 3 s.
GradeCaseSpec ball_rest() {
  GradeCaseSpec spec = grade_case_spec(
    "ball_rest", "balls of 1 kg and 50 kg resting on the ground",
    "at rest: no jiggle (under 1 cm/s after 1 s), no sinking (under 2 cm), whatever the mass",
    {3.0, true, {0.0f, 0.8f, 3.0f}, {0.0f, 0.2f, 0.0f}}, [=](demos::Scene& scene) {
    add_ground(scene, 0.5, 0.5);
    add_sphere(scene, "light", 0.25, 1.0, Vec3(-0.7, 0.25, 0), Vec3::Zero(), 0.5, 0.5);
    add_sphere(scene, "heavy", 0.25, 50.0, Vec3(0.7, 0.25, 0), Vec3::Zero(), 0.5, 0.5);
  });
  spec.judge = [](const Run& run) {
    double fastest = 0, light_depth = 0, heavy_depth = 0;
    for (size_t step = size_t(1.0 / run.dt); step < run.states.size(); ++step) {
      for (const char* name : {"light", "heavy"}) fastest = std::max(fastest, speed(run.body(step, name), 0.25));
      light_depth = std::max(light_depth, 0.25 - run.body(step, "light").position.y());
      heavy_depth = std::max(heavy_depth, 0.25 - run.body(step, "heavy").position.y());
    }
    std::vector<double> light_trace, heavy_trace;
    for (size_t step = 0; step < run.states.size(); ++step) {
      light_trace.push_back(0.25 - run.body(step, "light").position.y());
      heavy_trace.push_back(0.25 - run.body(step, "heavy").position.y());
    }
    Verdict verdict;
    verdict.expected = "under 1 cm/s; each under 2 cm deep, within 2 mm of each other";
    verdict.measured = format("%.1f cm/s; 1 kg %.2f cm deep, 50 kg %.2f cm", 100 * fastest, 100 * light_depth, 100 * heavy_depth);
    const bool still = fastest < 0.01, shallow = std::max(light_depth, heavy_depth) < 0.02;
    const bool alike = std::abs(heavy_depth - light_depth) < 0.002;
    verdict.passed = still && shallow && alike;
    if (!alike && heavy_depth > light_depth)
      verdict.hint = mass_blind_hint(run, "the heavier body sinks deeper");
    else if (!shallow && only_grew(light_trace) && only_grew(heavy_trace))
      verdict.hint = never_corrected_hint(std::max(light_depth, heavy_depth));
    else if (!still)
      verdict.hint = "a resting ball jiggles: restitution applied to every tiny approach bounces it each step. Bounce only "
                     "hits closing faster than about 0.5 m/s (ERRATA.md: restitution at resting contact)";
    else if (!shallow)
      verdict.hint = "they sink: gravity adds g dt of closing speed every step, and only the position correction takes it "
                     "back; make it stronger (a larger beta), or the slop smaller";
    else if (!alike)
      verdict.hint = "the light ball sinks deeper than the heavy one: the position correction must go through eq. 13's "
                     "denominator, as a speed, not as an impulse";
    return verdict;
  };
  return spec;
}

// A 1 kg box, 1 m a side, sliding at 3 m/s on the ground, mu = `mu` for both; for 1.5 s.
const CaseStage kSlideStage{1.5, true, {0.0f, 1.5f, 5.0f}, {0.0f, 0.4f, 0.0f}};
void add_sliding_box(demos::Scene& scene, double mu) {
  add_ground(scene, 0, mu);
  add_box(scene, "box", Vec3(0.5, 0.5, 0.5), 1.0, Vec3(-1.5, 0.5, 0), Vec3(3, 0, 0), 0, mu);
}

GradeCaseSpec slide_friction() {
  GradeCaseSpec spec = grade_case_spec(
    "slide_friction", "a box sliding to a stop, mu = 0.5",
    "Coulomb: it slows at mu g while it slides; from 3 m/s to 0.3 m/s in (3 - 0.3) / (mu g) s, over (3^2 - 0.3^2) / (2 mu g) m",
    kSlideStage, [](demos::Scene& scene) { add_sliding_box(scene, 0.5); });
  spec.judge = [](const Run& run) {
    const double mu = 0.5, v0 = 3, slow = 0.3;
    const double t_expected = (v0 - slow) / (mu * kG), d_expected = (v0 * v0 - slow * slow) / (2 * mu * kG);
    const double x0 = run.body(0, "box").position.x();
    Verdict verdict;
    verdict.expected = format("down to %.1f m/s after %.3f s and %.3f m", slow, t_expected, d_expected);
    double t = -1, d = 0;
    for (size_t step = 1; step < run.states.size() && t < 0; ++step) {
      const double before = horizontal(run.body(step - 1, "box").velocity), now = horizontal(run.body(step, "box").velocity);
      if (now > slow) continue;
      const double share = before > now ? (before - slow) / (before - now) : 1;  // where between the two steps
      t = (step - 1 + share) * run.dt;
      d = run.body(step - 1, "box").position.x() - x0 + share * (run.body(step, "box").position.x() - run.body(step - 1, "box").position.x());
    }
    double creep = 0;
    for (size_t step = run.states.size() - size_t(0.5 / run.dt); step < run.states.size(); ++step)
      creep = std::max(creep, horizontal(run.body(step, "box").velocity));
    if (t < 0) {
      verdict.measured = format("still sliding at %.2f m/s after %.1f s", horizontal(run.states.back()[1].velocity), run.dt * (run.states.size() - 1));
      verdict.hint = "friction did not stop it: the tangent impulse (lines 102-128) with mu = c0.m_friction, up to mu jn";
      return verdict;
    }
    verdict.measured = format("down to %.1f m/s after %.3f s and %.3f m; then creeps at up to %.2f m/s", slow, t, d, creep);
    verdict.passed = std::abs(t - t_expected) <= 0.05 * t_expected && std::abs(d - d_expected) <= 0.05 * d_expected;
    if (verdict.passed) return verdict;
    if (d < 0.5 * d_expected)
      verdict.hint = "it stopped almost at once: friction took all the sliding in one step. Coulomb's friction is at most mu "
                     "times the normal impulse: clamp jt to -mu jn .. mu jn (the listing's line 119 says it does not)";
    else
      verdict.hint = "friction's impulse while it slides is mu jn exactly (jn this contact's normal impulse), against the "
                     "sliding at the contact (the tangent of dv, lines 107-109)";
    return verdict;
  };
  return spec;
}

GradeCaseSpec slide_frictionless() {
  GradeCaseSpec spec = grade_case_spec(
    "slide_frictionless", "a box sliding without friction, mu = 0",
    "no friction: it keeps its 3 m/s and stays on the ground",
    kSlideStage, [](demos::Scene& scene) { add_sliding_box(scene, 0); });
  spec.judge = [](const Run& run) {
    double slowest = 1e9, lowest = 1e9, highest = -1e9;
    for (size_t step = 0; step < run.states.size(); ++step) {
      const physics::Body& box = run.body(step, "box");
      slowest = std::min(slowest, horizontal(box.velocity));
      lowest = std::min(lowest, box.position.y());
      highest = std::max(highest, box.position.y());
    }
    Verdict verdict;
    verdict.expected = "3.00 m/s throughout; its centre 0.48-0.52 m high";
    verdict.measured = format("%.2f m/s at the slowest; its centre %.3f-%.3f m high", slowest, lowest, highest);
    const bool kept = slowest >= 3 * 0.99, grounded = lowest >= 0.48 && highest <= 0.52;
    verdict.passed = kept && grounded;
    if (!kept)
      verdict.hint = "friction is 0 here, yet it slowed: the tangent impulse must be clamped to mu jn with mu = c0.m_friction, "
                     "which is 0 (the listing's line 119 does not clamp)";
    else if (!grounded)
      verdict.hint = lowest < 0.48 ? "it sank into the ground: see the resting balls" : "it hopped: a push bigger than the sinking it corrects";
    return verdict;
  };
  return spec;
}

// A solid ball (1 kg, R = 0.25 m; e = 0.5, mu = 0.5, and the ground's the same) dropped onto the
// ground, moving sideways at 2 m/s with backspin, +8 rad/s about z: its contact point slides
// forward at vx + wz R = 4 m/s. It first overlaps the ground by 1 mm at the start of step
// kLandingStep, meeting it at 2.94 m/s.
constexpr int kLandingStep = 18;
constexpr double kSpinRadius = 0.25, kSpinMass = 1, kSpinE = 0.5, kSpinMu = 0.5, kSpinVx = 2, kSpinWz = 8;
constexpr double kSpinShare = 0.03;  // of the sideways 2 m/s: how near vx' (and wz' R) must be

GradeCaseSpec bounce_spin() {
  GradeCaseSpec spec = grade_case_spec(
    "bounce_spin", "a ball bouncing with backspin, e = 0.5, mu = 0.5",
    "eq. 5 and Coulomb: it bounces, Jn = (1 + e) m |vy|; friction stops its contact point's sliding (vx + wz R) if "
    "that takes at most mu Jn, Jt = (vx + wz R) / (1/m + R^2/I), I = 2/5 m R^2, and it leaves rolling: "
    "vx' = vx - Jt/m, wz' = -vx'/R (each within 3 % of its 2 m/s, wz' times R)",
    {1.0, true, {0.0f, 0.7f, 3.5f}, {0.0f, 0.35f, 0.0f}}, [](demos::Scene& scene) {
    // Velocity first, then position: at the start of step n it has fallen g dt^2 n (n + 1) / 2.
    const double dt = scene.world.time_step, g = -scene.world.gravity.y();
    const double drop = g * dt * dt * kLandingStep * (kLandingStep + 1) / 2;
    add_ground(scene, kSpinE, kSpinMu);
    add_sphere(scene, "ball", kSpinRadius, kSpinMass, Vec3(-0.9, kSpinRadius - 0.001 + drop, 0), Vec3(kSpinVx, 0, 0), kSpinE, kSpinMu);
    scene.bodies.back().angular_velocity = Vec3(0, 0, kSpinWz);  // backspin: add_sphere sets no spin
  });
  spec.judge = [](const Run& run) {
    const double R = kSpinRadius, m = kSpinMass, inertia = 0.4 * m * R * R, tolerance = kSpinShare * kSpinVx;
    Verdict verdict;
    const int touch = run.first_touch("ball", "ground");  // its response moves states[touch] into states[touch + 1]
    if (touch < 0) {
      verdict.measured = "it never touched the ground";
      verdict.hint = "the ball fell through the ground: the listing's response only returns early for bodies moving apart";
      return verdict;
    }
    // The law, from the ball as it met the ground.
    const physics::Body& before = run.body(size_t(touch), "ball");
    const double vx0 = before.velocity.x(), vy0 = before.velocity.y(), wz0 = before.angular_velocity.z();
    const double slide0 = vx0 + wz0 * R;
    const double jn = (1 + kSpinE) * m * std::abs(vy0), stop = slide0 / (1 / m + R * R / inertia);
    const double jt = std::clamp(stop, -kSpinMu * jn, kSpinMu * jn);
    const double vx_expected = vx0 - jt / m, wz_expected = wz0 - jt * R / inertia;
    const bool sticks = std::abs(stop) <= kSpinMu * jn;
    verdict.expected = format("vx' %.3f m/s, wz' %.2f rad/s, within %.2f m/s (wz' R): %s, Jt %.2f N s %s mu Jn %.2f N s",
                              vx_expected, wz_expected, tolerance, sticks ? "it rolls" : "it slides",
                              std::abs(stop), sticks ? "<=" : ">", kSpinMu * jn);
    // The bounce: the first step whose vy turns from < 0 to > 0, which must be the landing's.
    size_t bounce = 0;
    for (size_t step = 1; step < run.states.size() && bounce == 0; ++step)
      if (run.body(step - 1, "ball").velocity.y() < 0 && run.body(step, "ball").velocity.y() > 0) bounce = step;
    const physics::Body& after = run.body(size_t(touch) + 1, "ball");
    const double vx1 = after.velocity.x(), wz1 = after.angular_velocity.z(), slide1 = vx1 + wz1 * R;
    if (bounce != size_t(touch) + 1) {
      const double left = after.velocity.y() + kG * run.dt;  // just after its impulse, before the step's gravity
      verdict.measured = format("no bounce: it met the ground at %.2f m/s and was at %.2f m/s after its impulse; vx' %.3f m/s, "
                                "wz' %.2f rad/s", std::abs(vy0), left, vx1, wz1);
      if (left < -0.25 * std::abs(vy0))
        verdict.hint = "it kept falling into the ground after it touched: Jn is too small. With eq. 8 and 13 as printed, "
                       "-(1 - e), the impulse is (1 - e)/(1 + e) of the one that bounces it; the listing's line 81 has -(1 + e)";
      else if (left < 0.25 * kSpinE * std::abs(vy0))
        verdict.hint = "it stopped dead on the ground instead of bouncing: e was 0. Use the pair's, c0.m_restitution (the "
                       "listing hard-codes float e = 0.0f, line 71); friction's bound, mu jn, grows with the bounce's jn too";
      else
        verdict.hint = "it did not leave the ground in the step it landed: eq. 5, the normal speed after is -e times the speed "
                       "before, from one impulse (1 + e) m |vy|";
      return verdict;
    }
    verdict.measured = format("vx' %.3f m/s, wz' %.2f rad/s: its contact point slides at %.2f m/s after (at %.2f before); it "
                              "rose at %.2f m/s", vx1, wz1, std::abs(slide1) < 0.005 ? 0.0 : slide1, slide0, after.velocity.y());
    verdict.passed = std::abs(vx1 - vx_expected) <= tolerance && std::abs(wz1 - wz_expected) * R <= tolerance;
    if (verdict.passed) return verdict;
    const double forward = slide0 >= 0 ? 1 : -1;  // the way the contact point slid when it landed
    if (std::abs(vx1 - vx0) <= tolerance && std::abs(wz1 - wz0) * R <= tolerance)
      verdict.hint = "the bounce got no friction: vx and the spin are what they were. Listing 1 applies the tangent impulse "
                     "right after the normal impulse of the same collision (lines 102-128), against the contact point's "
                     "sliding (the tangent of dv), up to mu times this collision's jn";
    else if (forward * slide1 < -tolerance)
      verdict.hint = "friction more than stopped the sliding: the contact point slides backwards after the bounce. Clamp jt "
                     "to mu jn, and to no more than the impulse that stops the contact point: -Dot(dv, tangent) / tangDiv, "
                     "eq. 13's denominator along the tangent (its r x t terms too: 1/m + R^2/I for a ball)";
    else if (std::abs(vx1 - vx_expected) <= tolerance)
      verdict.hint = "vx is right but the spin is not: friction's impulse turns the ball too, r0 x (jt tangent) through the "
                     "inverse inertia onto c0.m_angVelocity (and the opposite for c1)";
    else if (forward * (vx0 - vx1) < forward * (vx0 - vx_expected))
      verdict.hint = "friction stopped short: the contact point still slides after the bounce. The impulse that stops it is "
                     "-Dot(dv, tangent) / tangDiv, with tangDiv eq. 13's denominator along the tangent (1/m + R^2/I for a "
                     "ball); Coulomb cuts it to mu jn only where it is more";
    else
      verdict.hint = "friction took more than it may: at most the impulse that stops the contact point (-Dot(dv, tangent) / "
                     "tangDiv), and at most mu jn";
    return verdict;
  };
  return spec;
}

// Two boxes of 10 kg, 1 m a side, one on the other, left for 3 s.
GradeCaseSpec stack() {
  GradeCaseSpec spec = grade_case_spec(
    "stack", "two boxes of 10 kg stacked",
    "it stands: the top box stays on (within 10 cm of the bottom's centre), both upright (within 10 degrees), "
    "neither sinks more than 5 cm into what holds it",
    {3.0, true, {0.0f, 1.6f, 5.5f}, {0.0f, 0.9f, 0.0f}}, [=](demos::Scene& scene) {
    add_ground(scene, 0, 0.5);
    add_box(scene, "bottom", Vec3(0.5, 0.5, 0.5), 10, Vec3(0, 0.5, 0), Vec3::Zero(), 0, 0.5);
    add_box(scene, "top", Vec3(0.5, 0.5, 0.5), 10, Vec3(0, 1.5, 0), Vec3::Zero(), 0, 0.5);
  });
  spec.judge = [](const Run& run) {
    constexpr double kOff = 0.10, kLeaning = 10 * 3.14159265358979 / 180, kSunk = 0.05;
    // Each breach's first step (-1: none), so that the hint names the first thing that went wrong.
    double off = 0, leaning = 0, sunk = 0;
    long off_at = -1, leaning_at = -1, sunk_at = -1;
    std::vector<double> depth;  // the bottom's in the ground, and the top's in the bottom while it lies flat on it
    const int top_index = run.index_of("top"), bottom_index = run.index_of("bottom");
    double friction_before_off = 0, push_before_off = 0;  // N s, between the two boxes, until the top was 10 cm off
    for (size_t step = 0; step < run.states.size(); ++step) {
      const physics::Body& bottom = run.body(step, "bottom");
      const physics::Body& top = run.body(step, "top");
      const double shift = horizontal(top.position - bottom.position);
      // The top's depth is in what holds it: the bottom while it lies flat on it, the ground once
      // it lies flat beside it (tilted over the edge, neither).
      double top_depth = 0;
      if (tilt(top) < kLeaning / 2) top_depth = shift < 0.45 ? 1.0 - (top.position.y() - bottom.position.y()) : shift > 1.0 ? 0.5 - top.position.y() : 0;
      const double step_depth = std::max(0.5 - bottom.position.y(), top_depth);
      depth.push_back(step_depth);
      off = std::max(off, shift);
      leaning = std::max({leaning, tilt(bottom), tilt(top)});
      sunk = std::max(sunk, step_depth);
      if (off_at < 0 && shift > kOff) off_at = long(step);
      if (leaning_at < 0 && std::max(tilt(bottom), tilt(top)) > kLeaning) leaning_at = long(step);
      if (sunk_at < 0 && step_depth > kSunk) sunk_at = long(step);
      if (off_at < 0 && step > 0)
        for (const physics::ContactRecord& contact : run.contacts[step - 1])
          if ((contact.body_a == top_index && contact.body_b == bottom_index) || (contact.body_a == bottom_index && contact.body_b == top_index)) {
            friction_before_off += contact.tangent_impulse.norm();
            push_before_off += std::abs(contact.normal_impulse);
          }
    }
    const double walked = horizontal(run.states.back()[1].position);
    Verdict verdict;
    verdict.expected = "top within 10 cm; upright within 10 deg; sunk under 5 cm";
    verdict.measured = format("top %.1f cm off; leaning %.1f deg; sunk %.1f cm (the stack walked %.0f cm)", 100 * off,
                              leaning * 180 / 3.14159265358979, 100 * sunk, 100 * walked);
    const bool on = off <= kOff, upright = leaning <= kLeaning, held = sunk <= kSunk;
    verdict.passed = on && upright && held;
    auto first = [](long at, long other) { return at >= 0 && (other < 0 || at <= other); };
    if (!held && first(sunk_at, off_at) && first(sunk_at, leaning_at))
      verdict.hint = hack_fix_line(run.source) > 0 ? mass_blind_hint(run, "they sink")
                     : only_grew(depth)            ? never_corrected_hint(sunk)
                                                   : kTooWeak;
    // No friction: none but the rounding of the response's floats, read back from the momenta.
    else if (!on && first(off_at, leaning_at) && friction_before_off < 1e-4 * push_before_off)
      verdict.hint = "the top box slid off with no friction holding it: the contacts between the boxes took no tangent impulse "
                     "before it left. Listing 1 applies the tangent impulse right after the normal impulse (its lines 102-130), "
                     "against the contact point's sliding, up to mu jn with mu = c0.m_friction";
    else if (!on || !upright)
      verdict.hint = "the top box slid off or toppled: a contact pushes and never pulls (jn >= 0), and friction holds it "
                     "only up to mu jn; e applied to the small approaches of resting boxes throws them about";
    else if (!held)
      verdict.hint = kTooWeak;
    return verdict;
  };
  return spec;
}

}  // namespace

std::vector<GradeCaseSpec> contact_cases() { return {ball_rest(), slide_friction(), slide_frictionless(), bounce_spin(), stack()}; }

}  // namespace impulse::workshop
