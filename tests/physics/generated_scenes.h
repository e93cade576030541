// Seeded, generated scene files for the laws' tests: a scene is written as a lecturer's file, loaded
// (load_scene, build_world) and stepped, the law checked at every step. A case that breaks its law
// prints its seed and the path of its scene file, kept for `impulse simulate FILE` to replay. The
// generators draw their numbers from std::mt19937_64's raw output, which the standard fixes bit
// for bit, so a seed is the same scene on every machine, and with every compiler: draws are
// taken one statement (or one declarator) at a time, never two in one call's arguments or one
// operator's operands, whose order C++ leaves to the compiler (Draw::vector, vector_of_length).
//
//   IMPULSE_LAW_SEEDS=N  cases per law (default: each law's); IMPULSE_LAW_FIRST_SEED=S  start at seed S.
#pragma once
#include "demos/scene/scene_file.h"
#include "demos/scene/scene_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace impulse::demos::laws {


namespace fs = std::filesystem;
using physics::Real;
using physics::Vec3;

// Uniform numbers from the generator's raw 64 bits (std::uniform_real_distribution is not the
// same on every standard library).
class Draw {
 public:
  explicit Draw(uint64_t seed) : bits_(seed) {}
  double uniform(double low, double high) { return low + (high - low) * double(bits_() >> 11) * 0x1.0p-53; }
  int integer(int low, int high) { return low + int(bits_() % uint64_t(high - low + 1)); }  // low..high
  bool coin() { return bits_() & 1; }
  Vec3 vector(const Vec3& low, const Vec3& high) {  // x, then y, then z
    const double x = uniform(low.x(), high.x());
    const double y = uniform(low.y(), high.y());
    const double z = uniform(low.z(), high.z());
    return Vec3(x, y, z);
  }
  Vec3 vector(double low, double high) { return vector(Vec3::Constant(low), Vec3::Constant(high)); }

 private:
  std::mt19937_64 bits_;
};

// A scene file's text, built table by table.
class SceneText {
 public:
  explicit SceneText(const std::string& title, double duration) {
    text_ << "[scene]\ntitle = \"" << title << "\"\nduration = " << duration << "\n";
  }
  SceneText& line(const std::string& text) {
    text_ << text << "\n";
    return *this;
  }
  void sphere(const Vec3& position, double radius, double mass, const Vec3& velocity, double restitution,
              double friction, const Vec3& angular_velocity = Vec3::Zero()) {
    text_ << "[[body]]\nshape = \"sphere\"\nradius = " << number(radius) << "\nmass = " << number(mass)
          << "\nposition = " << vector(position) << "\nvelocity = " << vector(velocity)
          << "\nangular_velocity = " << vector(angular_velocity)
          << "\nrestitution = " << number(restitution) << "\nfriction = " << number(friction) << "\n";
  }
  void box(const Vec3& position, const Vec3& size, double mass, const Vec3& velocity, const Vec3& angular_velocity,
           const Vec3& rotation_degrees, double restitution, double friction) {
    text_ << "[[body]]\nshape = \"box\"\nsize = " << vector(size) << "\nmass = " << number(mass)
          << "\nposition = " << vector(position) << "\nvelocity = " << vector(velocity)
          << "\nangular_velocity = " << vector(angular_velocity) << "\nrotation = " << vector(rotation_degrees)
          << "\nrestitution = " << number(restitution) << "\nfriction = " << number(friction) << "\n";
  }
  // A capsule or cylinder (`shape`), its axis along its own y.
  void round(const char* shape, const Vec3& position, double radius, double height, double mass, const Vec3& velocity,
             const Vec3& angular_velocity, const Vec3& rotation_degrees, double restitution, double friction) {
    text_ << "[[body]]\nshape = \"" << shape << "\"\nradius = " << number(radius) << "\nheight = " << number(height)
          << "\nmass = " << number(mass) << "\nposition = " << vector(position) << "\nvelocity = " << vector(velocity)
          << "\nangular_velocity = " << vector(angular_velocity) << "\nrotation = " << vector(rotation_degrees)
          << "\nrestitution = " << number(restitution) << "\nfriction = " << number(friction) << "\n";
  }
  // A body of a shape written by the caller: its fields ("shape = \"wedge\"\nsize = [1, 0.5, 0.5]").
  void shaped(const std::string& shape_fields, const Vec3& position, double mass, const Vec3& velocity,
              const Vec3& angular_velocity, const Vec3& rotation_degrees, double restitution, double friction) {
    text_ << "[[body]]\n" << shape_fields << "\nmass = " << number(mass) << "\nposition = " << vector(position)
          << "\nvelocity = " << vector(velocity) << "\nangular_velocity = " << vector(angular_velocity)
          << "\nrotation = " << vector(rotation_degrees) << "\nrestitution = " << number(restitution)
          << "\nfriction = " << number(friction) << "\n";
  }
  std::string str() const { return text_.str(); }

  // 17 significant digits: the file holds the generator's numbers exactly.
  static std::string number(double value) {
    std::ostringstream out;
    out.precision(17);
    out << value;
    std::string text = out.str();
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
  }
  static std::string vector(const Vec3& v) {
    std::string text = "[";  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + string
    text += number(v.x()) + ", " + number(v.y()) + ", " + number(v.z());
    return text += "]";
  }

 private:
  std::ostringstream text_;
};

// A direction drawn evenly over the sphere (or the circle in the x-y plane).
inline Vec3 direction(Draw& draw, bool flat) {
  for (;;) {
    const double x = draw.uniform(-1, 1);
    const double y = draw.uniform(-1, 1);
    const Vec3 v(x, y, flat ? 0.0 : draw.uniform(-1, 1));
    const double length = v.norm();
    if (length > 0.1 && length <= 1) return v / length;
  }
}

// A direction, then a length from low to high.
inline Vec3 vector_of_length(Draw& draw, double low, double high) {
  const Vec3 along = direction(draw, false);
  return along * draw.uniform(low, high);
}

// A velocity of 0.2 to 4 m/s toward the middle of the scene, a little off.
inline Vec3 toward_middle(Draw& draw, const Vec3& at) {
  const double speed = draw.uniform(0.2, 4);
  return -at.normalized() * speed + vector_of_length(draw, 0, 0.5);
}

// Places bodies of the given bounding radii at random in a region, none overlapping another
// (an overlap at the start is pushed apart by the contacts' position correction, which adds
// energy: a start the laws are not about).
class Placement {
 public:
  Placement(Draw& draw, Vec3 low, Vec3 high) : draw_(draw), low_(low), high_(high) {}
  Vec3 place(double radius) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      const Vec3 at = draw_.vector(low_, high_);
      bool clear = true;
      for (const auto& [centre, r] : placed_) clear = clear && (at - centre).norm() > r + radius + 0.01;
      if (!clear) continue;
      placed_.push_back({at, radius});
      return at;
    }
    throw std::runtime_error("no room left for another body");
  }

 private:
  Draw& draw_;
  Vec3 low_, high_;
  std::vector<std::pair<Vec3, double>> placed_;
};

// What a law says of the world after a step, given the first record and the bodies as they were
// at the start: empty when it holds, else what broke.
using Law = std::function<std::string(const physics::World& world, const physics::StepRecord& start,
                                      const std::vector<physics::Body>& initial)>;

inline int seeds_per_law(int default_count) {
  const char* text = std::getenv("IMPULSE_LAW_SEEDS");
  return text ? std::max(1, std::atoi(text)) : default_count;
}
inline uint64_t first_seed() {
  const char* text = std::getenv("IMPULSE_LAW_FIRST_SEED");
  return text ? std::strtoull(text, nullptr, 10) : 1;
}

// Writes the case's scene, steps it to its duration checking the law at every step, and returns
// the first breach with the seed and the file to replay (empty when the law held throughout).
inline std::string run_case(const std::string& name, uint64_t seed, const std::string& scene_text, const Law& law) {
  const fs::path directory = fs::path(testing::TempDir()) / "impulse-laws";
  fs::create_directories(directory);
  const fs::path path = directory / (name + "-" + std::to_string(seed) + ".toml");
  std::ofstream(path) << "# " << name << ", seed " << seed << " (tests/physics/generated_laws_test.cpp, impact_laws_test.cpp)\n"
                      << scene_text;
  const Scene scene = load_scene(path.string());
  physics::World world = build_world(scene);
  const physics::StepRecord start = world.record();
  const std::vector<physics::Body> initial = world.bodies();
  const int steps = int(std::lround(scene.duration / scene.world.time_step));
  for (int step = 1; step <= steps; ++step) {
    world.step();
    const std::string breach = law(world, start, initial);
    if (!breach.empty()) {
      std::ostringstream report;
      report << name << ", seed " << seed << ", at " << world.time() << " s: " << breach << "\n  scene kept at "
             << path.string() << "; replay: impulse simulate " << path.string();
      return report.str();
    }
  }
  fs::remove(path);
  return "";
}

inline Draw draw_for(const std::string& name, uint64_t seed) { return Draw(seed * 0x9E3779B97F4A7C15ull + name.size()); }

// FNV-1a over the text of a generator's scenes for seeds 1..count: a constant of the test, the
// same from every build (GCC's and clang's order their draws alike only as the header says).
inline uint64_t scenes_hash(const std::string& name, const std::function<std::string(Draw&)>& generate, int count = 20) {
  uint64_t hash = 0xcbf29ce484222325ull;
  for (uint64_t seed = 1; seed <= uint64_t(count); ++seed) {
    Draw draw = draw_for(name, seed);
    for (const char c : generate(draw)) hash = (hash ^ uint8_t(c)) * 0x100000001b3ull;
  }
  return hash;
}

// Generates `default_count` scenes (IMPULSE_LAW_SEEDS) and checks the law in each.
inline void check_law(const std::string& name, int default_count, const std::function<std::string(Draw&)>& generate,
               const Law& law) {
  const uint64_t first = first_seed();
  const int count = seeds_per_law(default_count);
  int held = 0;
  for (uint64_t seed = first; seed < first + uint64_t(count); ++seed) {
    Draw draw = draw_for(name, seed);
    const std::string breach = run_case(name, seed, generate(draw), law);
    if (breach.empty())
      ++held;
    else
      ADD_FAILURE() << breach;
  }
  std::printf("%s: held in %d of %d generated scenes (seeds %llu..%llu)\n", name.c_str(), held, count,
              static_cast<unsigned long long>(first), static_cast<unsigned long long>(first + count - 1));
}

inline std::string breach_text(const char* what, double measured, double limit) {
  std::ostringstream text;
  text.precision(9);
  text << what << " " << measured << " (limit " << limit << ")";
  return text.str();
}

}  // namespace impulse::demos::laws
