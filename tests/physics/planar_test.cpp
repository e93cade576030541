// The planar lock (physics/planar.h): a locked body moves in its plane and turns about its axis
// only, and the impulses it takes are the constrained body's.
#include "physics/world.h"
#include "tests/physics/physics_test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace impulse::physics {
namespace {

using test::add_ground;
using test::add_sphere;

constexpr int kZ = 2;  // the blackboard's plane is x-y

// A Galton board: rows of static pegs, each row shifted by half a pitch, with a ball dropped into
// it a little off the middle. The pegs are set 1 mm in front of or behind the plane, row by row
// (a real board's imprecision), so each touch pushes the ball out of the plane unless it is held.
struct Board {
  World world;
  int ball = -1;
};

Board galton_board(int ball_axis) {
  Board board;
  World& world = board.world;
  add_ground(world, 0.3, 0.3);
  constexpr Real kPeg = 0.03, kPitch = 0.12, kBall = 0.025;
  for (int row = 0; row < 8; ++row)
    for (int column = -4; column <= 4; ++column) {
      BodyDef peg;
      peg.name = "peg";
      peg.is_static = true;
      peg.shape = Shape::sphere(kPeg);
      peg.material = {0.5, 0.3};
      peg.position = Vec3(kPitch * (column + (row % 2 ? 0.5 : 0)), 0.3 + kPitch * row, row % 2 ? 0.001 : -0.001);
      world.add_body(peg);
    }
  BodyDef ball;
  ball.name = "ball";
  ball.shape = Shape::sphere(kBall);
  ball.mass = 0.05;
  ball.material = {0.5, 0.3};
  ball.position = Vec3(0.013, 0.3 + kPitch * 8, 0);
  ball.planar_axis = ball_axis;
  board.ball = world.add_body(ball);
  return board;
}

// The largest |z| of the ball's centre and |w_x|, |w_y| of its spin over 4 s, and its lowest centre.
struct Excursion {
  Real z = 0, spin_off_axis = 0, turn_off_axis = 0, lowest = INFINITY;
  int peg_touches = 0;  // steps with a contact between the ball and a peg
};

Excursion drop_through(Board& board) {
  Excursion most;
  for (int step = 0; step < 240; ++step) {
    board.world.step();
    const Body& ball = board.world.bodies()[board.ball];
    most.z = std::max(most.z, std::abs(ball.position.z()));
    most.spin_off_axis = std::max({most.spin_off_axis, std::abs(ball.angular_velocity.x()), std::abs(ball.angular_velocity.y())});
    // Started unturned: its orientation is its turn since, a rotation about z only (x = y = 0).
    most.turn_off_axis = std::max({most.turn_off_axis, std::abs(ball.orientation.x()), std::abs(ball.orientation.y())});
    most.lowest = std::min(most.lowest, ball.position.y());
    for (const ContactRecord& contact : board.world.record().contacts)
      if ((contact.body_a == board.ball && contact.body_b > 0) || (contact.body_b == board.ball && contact.body_a > 0)) {
        ++most.peg_touches;
        break;
      }
  }
  return most;
}

// The lock keeps the ball in its plane and turning about z alone, through every peg; the same
// board without it pushes the ball out of the plane (so the board is a test of the lock).
TEST(Planar, ABallFallingThroughAGaltonBoardStaysInItsPlane) {
  Board free = galton_board(kNotPlanar);
  const Excursion unlocked = drop_through(free);
  ASSERT_GT(unlocked.z, 1e-4) << "the board's offset pegs must push a free ball out of the plane";

  Board locked = galton_board(kZ);
  const Excursion held = drop_through(locked);
  EXPECT_GE(held.peg_touches, 10) << "the ball must meet the pegs";
  EXPECT_LT(held.lowest, 0.3) << "the ball must have passed the lowest row of pegs";
  EXPECT_LE(held.z, 1e-9);
  EXPECT_LE(held.spin_off_axis, 1e-12);
  EXPECT_LE(held.turn_off_axis, 1e-12);
}

// The lock's inertia: a body turning about a fixed axis e takes an angular impulse L as
// dw = e (e . L) / I_ee, I_ee its moment about that axis. A box of edges a, b, c turned only about
// z has I_zz = m (a^2 + b^2) / 12 whatever the angle.
TEST(Planar, AnAngularImpulseTurnsALockedBodyAboutItsAxisBy1OverIzz) {
  BodyDef def;
  def.shape = Shape::box(Vec3(0.5, 0.1, 0.2));
  def.mass = 3;
  def.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3::UnitZ()));
  def.planar_axis = kZ;
  const Body body = make_body(def);
  const Vec3 impulse(0.4, -1.3, 2.0);
  const Vec3 dw = body.inv_inertia_world * impulse;
  const Real izz = 3 * (1.0 * 1.0 + 0.2 * 0.2) / 12;
  EXPECT_EQ(dw.x(), 0);
  EXPECT_EQ(dw.y(), 0);
  EXPECT_NEAR(dw.z(), 2.0 / izz, 1e-12 * 2.0 / izz);
}

// A ball hits the end face of a locked box tilted 30 degrees about x (so its moment about z is
// not a principal one: free, it would wobble), off its centre, elastic and frictionless. Eq. 13
// with the constrained box's inverse mass and its 1 / I_zz gives the impulse
// J = (1 + e) v / (1/m_ball + 1/m_box + d^2 / I_zz), d the lever arm about z; after it, the ball,
// the box's velocity and its spin about z are as J says, and the kinetic energy is kept.
TEST(Planar, AFrictionlessHitOnALockedBodyIsEq13WithItsMomentAboutTheAxis) {
  World world(test::without_gravity());
  const Real half_x = 0.5, half_y = 0.1, half_z = 0.2, box_mass = 2, ball_mass = 1, radius = 0.1, d = 0.08, speed = 2;
  BodyDef box;
  box.name = "box";
  box.shape = Shape::box(Vec3(half_x, half_y, half_z));
  box.mass = box_mass;
  box.material = {1, 0};
  const Real tilt = kPi / 6;
  box.orientation = Quat(Eigen::AngleAxisd(tilt, Vec3::UnitX()));
  box.planar_axis = kZ;
  const int box_id = world.add_body(box);
  const int ball_id = add_sphere(world, Vec3(half_x + radius + 0.05, d, 0), radius, ball_mass, Vec3(-speed, 0, 0), {1, 0});
  world.body(ball_id).planar_axis = kZ;
  for (int step = 0; step < 30; ++step) world.step();

  // The box's moment about z: the local moments (edges 2 half_*) turned by the tilt about x.
  const Real iyy = box_mass * (4 * half_x * half_x + 4 * half_z * half_z) / 12;
  const Real izz_local = box_mass * (4 * half_x * half_x + 4 * half_y * half_y) / 12;
  const Real izz = iyy * std::sin(tilt) * std::sin(tilt) + izz_local * std::cos(tilt) * std::cos(tilt);
  // The point of impact is (half_x, d) from the box's centre, the normal x: r x n = -d z.
  const Real impulse = 2 * speed / (1 / ball_mass + 1 / box_mass + d * d / izz);
  const Body& after_ball = world.bodies()[ball_id];
  const Body& after_box = world.bodies()[box_id];
  const Real tolerance = 1e-6 * speed;
  EXPECT_NEAR(after_ball.velocity.x(), -speed + impulse / ball_mass, tolerance);
  EXPECT_NEAR(after_box.velocity.x(), -impulse / box_mass, tolerance);
  EXPECT_NEAR(after_box.angular_velocity.z(), impulse * d / izz, tolerance / d);
  EXPECT_EQ(after_box.angular_velocity.x(), 0);
  EXPECT_EQ(after_box.angular_velocity.y(), 0);
  const Real energy = ball_mass * after_ball.velocity.squaredNorm() / 2 + box_mass * after_box.velocity.squaredNorm() / 2 +
                      izz * after_box.angular_velocity.z() * after_box.angular_velocity.z() / 2;
  EXPECT_NEAR(energy, ball_mass * speed * speed / 2, 1e-6 * ball_mass * speed * speed);
}

// The lock takes only what leaves the plane: a locked ball set moving and spinning out of it
// between steps moves on in the plane as a free one does, spinning about z as it did.
TEST(Planar, TheLockTakesOnlyWhatLeavesThePlane) {
  World world;
  const int free_ball = add_sphere(world, Vec3(0, 5, 0), 0.1, 1, Vec3(1, 0, 1));
  const int held_ball = add_sphere(world, Vec3(3, 5, 0), 0.1, 1);
  world.body(held_ball).planar_axis = kZ;
  world.body(held_ball).velocity = Vec3(1, 0, 1);
  world.body(held_ball).angular_velocity = Vec3(2, 3, 4);
  world.step();
  const Real dt = world.settings().time_step;
  EXPECT_DOUBLE_EQ(world.bodies()[free_ball].position.z(), dt);
  EXPECT_EQ(world.bodies()[held_ball].position.z(), 0);
  EXPECT_EQ(world.bodies()[held_ball].velocity.z(), 0);
  EXPECT_NEAR(world.bodies()[held_ball].velocity.x(), 1, 1e-12);
  EXPECT_NEAR(world.bodies()[held_ball].velocity.y(), world.bodies()[free_ball].velocity.y(), 1e-12);
  EXPECT_EQ(world.bodies()[held_ball].angular_velocity, Vec3(0, 0, 4));
}

}  // namespace
}  // namespace impulse::physics
