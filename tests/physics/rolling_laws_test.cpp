// Rolling as laws over generated scenes (generated_scenes.h): the same impulses, another inertia.
// A ball of radius R and moment of inertia k m R^2 let go on an incline of angle theta rolls
// without slipping where friction allows it (mu >= k / (1 + k) tan theta), and then
//   m a = m g sin theta - F,  I alpha = F R,  a = alpha R   =>   a = g sin theta / (1 + k)
// whatever its mass and radius: 5/7 of g sin theta for a solid ball (k = 2/5), 3/5 for a hollow one
// (a thin shell, k = 2/3, `inertia = "hollow"`), and 1 / (1 + k) for three moments given
// (`inertia = [I, I, I]`). The rolling race of section 4: the solid ball first, the shell after.
// Section 5's race: a solid ball (k = 2/5), a solid cylinder (1/2) and a ring (a hollow cylinder,
// k = 1): 5/7, 2/3 and 1/2 of g sin theta. A cylinder rolling on a flat keeps its speed and axis.
#include "tests/physics/generated_scenes.h"

#include <functional>
#include <memory>

namespace impulse::demos {
namespace {

using namespace laws;
using physics::Real;
using physics::Vec3;

constexpr double kG = 9.81;
constexpr double kFirst = 0.5, kLast = 1.5;  // s: the speeds compared (the contact settled by the first)

// The incline of `degrees` (up: its normal), as a tilted plane or (by a coin) a static box turned
// as a ramp, 40 m long and `width` across.
std::string incline(Draw& draw, double degrees, const Vec3& up, double friction, double width) {
  std::ostringstream text;
  if (draw.coin())
    text << "[[body]]\nname = \"incline\"\nshape = \"plane\"\nnormal = " << SceneText::vector(up) << "\nfriction = "
         << SceneText::number(friction) << "\n";
  else
    text << "[[body]]\nname = \"incline\"\nshape = \"box\"\nstatic = true\nsize = " << SceneText::vector(Vec3(40, 0.5, width))
         << "\nposition = " << SceneText::vector(-0.25 * up) << "\nrotation = " << SceneText::vector(Vec3(0, 0, -degrees))
         << "\nfriction = " << SceneText::number(friction) << "\n";
  return text.str();
}

// The incline's normal, from the first body as it was built.
Vec3 incline_up(const physics::Body& incline) {
  return incline.shape.type == physics::ShapeType::plane ? incline.shape.normal : Vec3(incline.orientation * Vec3::UnitY());
}

// An incline of 10 to 30 degrees (a tilted plane, or a static box turned as a ramp) and three balls
// across it: solid, hollow, and one of moments drawn between 0.1 and 1 m R^2. Friction enough to
// roll, from 1.5 times what the steepest needs to 1.
std::string rolling_race(Draw& draw) {
  const double degrees = draw.uniform(10, 30), theta = degrees * physics::kPi / 180;
  const Vec3 up(std::sin(theta), std::cos(theta), 0);
  const double k = draw.uniform(0.1, 1);
  const double friction = draw.uniform(1.5 * std::max(k, 2.0 / 3) / (1 + std::max(k, 2.0 / 3)) * std::tan(theta), 1.0);
  std::ostringstream text;
  text << "[scene]\ntitle = \"rolling race\"\nduration = " << SceneText::number(kLast) << "\n";
  text << incline(draw, degrees, up, friction, 6);
  const char* inertia[3] = {"\"solid\"", "\"hollow\"", nullptr};
  for (int i = 0; i < 3; ++i) {
    const double radius = draw.uniform(0.05, 0.3);
    const double mass = draw.uniform(0.1, 5);
    const double moment = k * mass * radius * radius;
    text << "[[body]]\nname = \"ball " << i << "\"\nshape = \"sphere\"\nradius = " << SceneText::number(radius)
         << "\nmass = " << SceneText::number(mass) << "\nfriction = " << SceneText::number(friction)
         << "\nposition = " << SceneText::vector(radius * up + Vec3(0, 0, i - 1.0)) << "\ninertia = "
         << (inertia[i] ? std::string(inertia[i]) : SceneText::vector(Vec3::Constant(moment))) << "\n";
  }
  return text.str();
}

// Each racer's acceleration down the incline between kFirst and kLast (the contact settled by
// the first) against g sin theta / (1 + k), `k(body, i)` the i-th racer's I / (m R^2); with
// `across`, a cylinder's axis stays across the slope (along z).
Law race_law(std::function<double(const physics::Body&, size_t)> k_of, bool across) {
  auto first = std::make_shared<std::vector<double>>();  // each racer's speed down the incline at kFirst
  return [first, k_of, across](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
    const Vec3 up = incline_up(initial[0]);
    const Vec3 down(up.y(), -up.x(), 0);
    const double t = world.time();
    if (std::abs(t - kFirst) < 1e-9) {
      first->clear();
      for (size_t i = 1; i < world.bodies().size(); ++i) first->push_back(world.bodies()[i].velocity.dot(down));
    }
    if (std::abs(t - kLast) > 1e-9) return std::string();
    for (size_t i = 1; i < world.bodies().size(); ++i) {
      const physics::Body& body = world.bodies()[i];
      const double k = k_of(body, i), expected = kG * up.x() / (1 + k);
      const double measured = (body.velocity.dot(down) - (*first)[i - 1]) / (kLast - kFirst);
      if (std::abs(measured - expected) > 0.01 * expected) {
        std::ostringstream what;
        what << body.name << " (k = " << k << "): acceleration down the incline (m/s^2), to be g sin theta / (1 + k) within 1 %:";
        return breach_text(what.str().c_str(), measured, expected);
      }
      const Vec3 axis = body.orientation * Vec3::UnitY();
      if (across && body.shape.type == physics::ShapeType::cylinder && std::abs(axis.z()) < 1 - 1e-4)
        return breach_text((body.name + ": its axis turned off the line across the slope: |axis . z| (to stay 1 within 1e-4)").c_str(),
                           std::abs(axis.z()), 1);
    }
    return std::string();
  };
}

TEST(RollingLaws, ABallRollsDownAnInclineAtGSinThetaOverOnePlusK) {
  check_law("rolling-race", 40, rolling_race, race_law([](const physics::Body& ball, size_t i) {
              const double ks[2] = {0.4, 2.0 / 3};  // solid, hollow; the third's moments are given
              return i == 3 ? ball.inertia_local(0, 0) / (ball.mass * ball.shape.radius * ball.shape.radius) : ks[i - 1];
            }, false));
}

// The incline (as rolling_race's) and across it a solid ball, a solid cylinder and a ring, the
// cylinders' axes across the slope (along z), each of its own size and mass.
std::string cylinder_race(Draw& draw) {
  const double degrees = draw.uniform(10, 30), theta = degrees * physics::kPi / 180;
  const Vec3 up(std::sin(theta), std::cos(theta), 0);
  const double friction = draw.uniform(1.5 * 0.5 * std::tan(theta), 1.0);  // a ring needs mu >= tan(theta) / 2
  std::ostringstream text;
  text << "[scene]\ntitle = \"cylinder race\"\nduration = " << SceneText::number(kLast) << "\n";
  text << incline(draw, degrees, up, friction, 8);
  for (int i = 0; i < 3; ++i) {
    const double radius = draw.uniform(0.05, 0.3);
    const double mass = draw.uniform(0.1, 5);
    const double half_height = draw.uniform(0.05, 0.4);
    text << "[[body]]\nname = \"" << (i == 0 ? "ball" : i == 1 ? "cylinder" : "ring") << "\"\nshape = \""
         << (i == 0 ? "sphere" : "cylinder") << "\"\nradius = " << SceneText::number(radius) << "\nmass = " << SceneText::number(mass)
         << "\nfriction = " << SceneText::number(friction) << "\nposition = " << SceneText::vector(radius * up + Vec3(0, 0, 2.5 * (i - 1)))
         << "\n";
    if (i > 0)
      text << "height = " << SceneText::number(2 * half_height) << "\nrotation = [90.0, 0.0, 0.0]\ninertia = \""
           << (i == 1 ? "solid" : "hollow") << "\"\n";
  }
  return text.str();
}

TEST(RollingLaws, ABallACylinderAndARingRollDownAtFiveSeventhsTwoThirdsAndAHalfOfGSinTheta) {
  const double ks[3] = {0.4, 0.5, 1.0};  // I / (m R^2): a solid ball, a solid cylinder, a ring
  check_law("cylinder-race", 20, cylinder_race, race_law([ks](const physics::Body&, size_t i) { return ks[i - 1]; }, true));
}

// A cylinder rolling on the ground (a plane or a static box), its axis along x or z, at 0.5 to 4
// m/s: its speed after 5 s within 0.1 % of the start's, its axis where it was within 1e-4.
std::string cylinder_rolling(Draw& draw) {
  const double radius = draw.uniform(0.05, 0.4), half_height = draw.uniform(0.05, 0.5), speed = draw.uniform(0.5, 4);
  const bool along_x = draw.coin();  // the axis along x, rolling along z; else the other way round
  std::ostringstream text;
  text << "[scene]\ntitle = \"a rolling cylinder\"\nduration = 5\n";
  if (draw.coin())
    text << "[[body]]\nname = \"ground\"\nshape = \"plane\"\n";
  else
    text << "[[body]]\nname = \"ground\"\nshape = \"box\"\nstatic = true\nsize = [60.0, 1.0, 60.0]\nposition = [0.0, -0.5, 0.0]\n";
  const Vec3 velocity = along_x ? Vec3(0, 0, speed) : Vec3(speed, 0, 0);
  const Vec3 spin = along_x ? Vec3(speed / radius, 0, 0) : Vec3(0, 0, -speed / radius);  // v = w x r rolling: no slip
  text << "[[body]]\nname = \"cylinder\"\nshape = \"cylinder\"\nradius = " << SceneText::number(radius) << "\nheight = "
       << SceneText::number(2 * half_height) << "\nmass = " << SceneText::number(draw.uniform(0.2, 5)) << "\nfriction = "
       << SceneText::number(draw.uniform(0.2, 1)) << "\nposition = " << SceneText::vector(Vec3(0, radius, 0) - 10 * velocity.normalized())
       << "\nrotation = " << (along_x ? "[0.0, 0.0, 90.0]" : "[90.0, 0.0, 0.0]") << "\nvelocity = " << SceneText::vector(velocity)
       << "\nangular_velocity = " << SceneText::vector(spin) << "\n";
  return text.str();
}

TEST(RollingLaws, ACylinderRollingOnAFlatKeepsItsSpeedAndItsAxis) {
  check_law("cylinder-rolling", 10, cylinder_rolling,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
              const physics::Body& start = initial[1];
              const physics::Body& now = world.bodies()[1];
              const Vec3 axis = now.orientation * Vec3::UnitY(), was = start.orientation * Vec3::UnitY();
              if (std::abs(axis.dot(was)) < 1 - 1e-4)
                return breach_text("the cylinder's axis turned: |axis . axis at the start| (to stay 1 within 1e-4)", std::abs(axis.dot(was)), 1);
              if (world.time() < 5 - 1e-9) return std::string();
              const double change = std::abs(now.velocity.norm() / start.velocity.norm() - 1);
              return change > 1e-3 ? breach_text("the speed's change after 5 s, relative (to be under 0.1 %)", change, 1e-3) : std::string();
            });
}

// A cylinder standing on its face, set turning about a point of its rim (no slip: friction 1, no
// bounce) with k times the energy that lifts its centre over that point, m g (sqrt(r^2 + h^2) - h),
// h its half height: about the rim, I = m (r^2/4 + h^2/3) + m (r^2 + h^2). k 1.6: it topples and
// lies on its side; k 0.6: it falls back and stands.
std::string cylinder_tipped(Draw& draw) {
  const double r = draw.uniform(0.05, 0.2), h = r * draw.uniform(1.5, 4), k = draw.coin() ? 1.6 : 0.6;
  const double lift = kG * (std::hypot(r, h) - h), moment = r * r / 4 + h * h / 3 + r * r + h * h;  // per unit mass
  const double w = std::sqrt(2 * k * lift / moment);
  std::ostringstream text;
  text << "[scene]\ntitle = \"a cylinder tipped\"\nduration = 3\n# k = " << k << "\n[[body]]\nname = \"ground\"\nshape = \"plane\"\n"
       << "restitution = 0\nfriction = 1\n[[body]]\nname = \"cylinder\"\nshape = \"cylinder\"\nradius = " << SceneText::number(r)
       << "\nheight = " << SceneText::number(2 * h) << "\nmass = 1\nrestitution = 0\nfriction = 1\nposition = "
       << SceneText::vector(Vec3(0, h, 0)) << "\nvelocity = " << SceneText::vector(Vec3(w * h, w * r, 0))
       << "\nangular_velocity = " << SceneText::vector(Vec3(0, 0, -w)) << "\n";
  return text.str();
}

TEST(RollingLaws, ACylinderToppledWithEnoughEnergyToLiftItsCentreOverItsRimAndNotWithLess) {
  check_law("cylinder-tipped", 20, cylinder_tipped,
            [](const physics::World& world, const physics::StepRecord&, const std::vector<physics::Body>& initial) {
              if (world.time() < 3 - 1e-9) return std::string();
              const physics::Body& start = initial[1];
              const physics::Body& now = world.bodies()[1];
              const double r = start.shape.radius, h = start.shape.half_height;
              const double lift = kG * (std::hypot(r, h) - h), moment = r * r / 4 + h * h / 3 + r * r + h * h;
              const double k = 0.5 * moment * start.angular_velocity.squaredNorm() / lift;
              const double upright = std::abs((now.orientation * Vec3::UnitY()).y());
              if (k > 1 && upright > 0.05) return breach_text("toppled with 1.6 times the energy, it stands: |axis . y| (to be under 0.05)", upright, 0.05);
              if (k < 1 && upright < 0.999) return breach_text("with 0.6 times the energy, it fell: |axis . y| (to stay above 0.999)", upright, 0.999);
              return std::string();
            });
}

// The incline's hollow ball is a thin shell, 5/3 of a solid ball's moment; a hollow cube's is a
// closed form too: 5 m L^2 / 18 for a side L (each face a thin plate).
TEST(RollingLaws, AHollowBodysInertiaIsItsShells) {
  physics::BodyDef ball;
  ball.shape = physics::Shape::sphere(0.3);
  ball.mass = 2;
  ball.spread = physics::MassSpread::hollow;
  const physics::Body shell = physics::make_body(ball);
  EXPECT_NEAR(shell.inertia_local(0, 0), 2.0 / 3 * 2 * 0.09, 1e-15);
  EXPECT_NEAR(shell.inertia_local(1, 1), shell.inertia_local(2, 2), 0);
  physics::BodyDef cube;
  cube.shape = physics::Shape::box(Vec3::Constant(0.5));
  cube.mass = 3;
  cube.spread = physics::MassSpread::hollow;
  const physics::Body box = physics::make_body(cube);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(box.inertia_local(axis, axis), 5.0 * 3 * 1.0 / 18, 1e-12);
  // A flat hollow box (a closed tray of 2a x 2b x 2c): the six plates summed by hand.
  physics::BodyDef tray;
  tray.shape = physics::Shape::box(Vec3(0.4, 0.1, 0.2));
  tray.mass = 1;
  tray.spread = physics::MassSpread::hollow;
  const physics::Body flat = physics::make_body(tray);
  const double a = 0.4, b = 0.1, c = 0.2, total = b * c + a * c + a * b;
  const double mx = b * c / total, my = a * c / total, mz = a * b / total;
  EXPECT_NEAR(flat.inertia_local(0, 0), mx * (b * b + c * c) / 3 + my * (c * c / 3 + b * b) + mz * (b * b / 3 + c * c), 1e-15);
  EXPECT_NEAR(flat.inertia_local(1, 1), my * (a * a + c * c) / 3 + mx * (c * c / 3 + a * a) + mz * (a * a / 3 + c * c), 1e-15);
  EXPECT_NEAR(flat.inertia_local(2, 2), mz * (a * a + b * b) / 3 + mx * (b * b / 3 + a * a) + my * (a * a / 3 + b * b), 1e-15);
  EXPECT_EQ(flat.inertia_local(0, 1), 0);
}

TEST(RollingLaws, GivenMomentsTakeThePlaceOfTheShapesAndMustBeARigidBodys) {
  physics::BodyDef def;
  def.shape = physics::Shape::box(Vec3(0.5, 0.2, 0.1));
  def.mass = 1;
  def.principal_inertia = Vec3(0.01, 0.02, 0.025);
  EXPECT_EQ(physics::make_body(def).inertia_local.diagonal(), def.principal_inertia);
  def.principal_inertia = Vec3(0.01, 0.02, 0.04);  // larger than the other two together
  EXPECT_THROW(physics::make_body(def), std::invalid_argument);
  def.principal_inertia = Vec3(0.01, 0, 0.01);
  EXPECT_THROW(physics::make_body(def), std::invalid_argument);
}

// As GeneratedLaws.ASeedIsTheSameSceneWhateverTheCompiler, for this generator.
TEST(RollingLaws, ASeedIsTheSameSceneWhateverTheCompiler) {
  EXPECT_EQ(scenes_hash("rolling-race", rolling_race), 0x51e0917e46c28396ull);
  EXPECT_EQ(scenes_hash("cylinder-race", cylinder_race), 0x2760dac125e73443ull);
  EXPECT_EQ(scenes_hash("cylinder-rolling", cylinder_rolling), 0x506366fbe78fa119ull);
  EXPECT_EQ(scenes_hash("cylinder-tipped", cylinder_tipped), 0x7800e87b4ee7c7d3ull);
}

}  // namespace
}  // namespace impulse::demos
