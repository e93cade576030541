// physics_bench: the scenes of ../shared/bench/SCENES.md in impulse and in Bullet, in one run of
// this program, with the ratio of their median costs per step. Each engine's run of each scene is
// a forked child, so that its peak memory (the child's ru_maxrss) is its own.
//
//   physics_bench                 the whole table (several minutes)
//   physics_bench --quick         every scene for a few steps (a smoke test)
//   physics_bench --scene NAME    one scene: stack-10, stack-20, pyramid, large-pyramid, boxes, spheres
#include "tests/bench/physics_scenes.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#ifndef IMPULSE_BUILD_TYPE
#define IMPULSE_BUILD_TYPE ""
#endif

namespace impulse::bench {
std::string impulse_description();  // impulse_scenes.cpp
}

namespace {

using namespace impulse::bench;

enum class EngineId { impulse, bullet };
const char* engine_name(EngineId e) { return e == EngineId::impulse ? "impulse" : "Bullet"; }

struct Measured {
  RunResult result;
  double peak_mib = 0;
};

// The runs of SCENES.md, in its order; then boxes and spheres with sleeping off, which the
// issue's speed goal asks for.
std::vector<Run> full_runs() {
  return {
      {"stack-10", 3600, false},     {"stack-10", 3600, true},  {"stack-20", 3600, false}, {"stack-20", 3600, true},
      {"pyramid", 600, false},       {"pyramid", 600, true},    {"pyramid", 3600, false},  {"pyramid", 3600, true},
      {"large-pyramid", 500, false}, {"boxes", 1200, true},     {"spheres", 1200, true},
      {"boxes", 1200, false, true},  {"spheres", 1200, false, true},
  };
}

std::string first_line_of(const char* path, const char* prefix) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) {
      const size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  return "?";
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return text;
}

bool read_all(int fd, void* data, size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = read(fd, p, size);
    if (got <= 0) return false;
    p += got;
    size -= size_t(got);
  }
  return true;
}

// Runs `work` in a forked child; returns what it wrote and the child's peak RSS in MiB.
template <class Work>
Measured in_child(Work work) {
  Measured m;
  int fds[2];
  std::fflush(nullptr);
  if (pipe(fds) != 0) {
    std::snprintf(m.result.error, sizeof m.result.error, "pipe: %s", std::strerror(errno));
    return m;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    std::snprintf(m.result.error, sizeof m.result.error, "fork: %s", std::strerror(errno));
    close(fds[0]);
    close(fds[1]);
    return m;
  }
  if (pid == 0) {
    close(fds[0]);
    RunResult r;
    try {
      work(r);
    } catch (const std::exception& e) {
      r.ok = false;
      std::snprintf(r.error, sizeof r.error, "%s", e.what());
    }
    const bool sent = write(fds[1], &r, sizeof r) == ssize_t(sizeof r);
    close(fds[1]);
    _exit(sent ? 0 : 1);
  }
  close(fds[1]);
  const bool got = read_all(fds[0], &m.result, sizeof m.result);
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  m.peak_mib = double(usage.ru_maxrss) / 1024;  // KiB on Linux
  if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    m.result.ok = false;
    if (WIFSIGNALED(status)) std::snprintf(m.result.error, sizeof m.result.error, "child killed by signal %d", WTERMSIG(status));
    else if (!got) std::snprintf(m.result.error, sizeof m.result.error, "child sent no result");
  }
  return m;
}

std::string run_length(int steps) {
  char text[32];
  if (steps % 60 == 0) std::snprintf(text, sizeof text, "%d s", steps / 60);
  else std::snprintf(text, sizeof text, "%d steps", steps);
  return text;
}

std::string metres(double m) {
  if (m < 0) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", m);
  return text;
}

std::string asleep_text(const Run& run, const RunResult& r) {
  if (!run.sleep) return "-";
  if (r.asleep_at < 0) return "never";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f s", r.asleep_at);
  return text;
}

void print_header() {
  std::printf("%-14s %6s %-9s %-5s %-8s %8s %8s %8s %6s %9s %9s %9s %6s %5s %8s\n", "scene", "bodies", "run", "sleep",
              "engine", "median", "p90", "max", "ratio", "top drift", "any drift", "asleep at", "moving", "sunk",
              "peak MiB");
  std::printf("%-14s %6s %-9s %-5s %-8s %8s %8s %8s %6s %9s %9s %9s %6s %5s %8s\n", "", "", "", "", "", "ms/step",
              "ms/step", "ms/step", "i/B", "m", "m", "", ">5cm/s", "y<0", "");
}

void print_row(const Run& run, EngineId engine, const Measured& m, std::optional<double> ratio) {
  const RunResult& r = m.result;
  const bool first = engine == EngineId::impulse;
  const std::string scene = first ? run.scene + (run.extra ? "*" : "") : "";
  const std::string bodies = first ? std::to_string(make_scene(run.scene).dynamic_count()) : "";
  const std::string length = first ? run_length(run.steps) : "";
  const char* sleep = first ? (run.sleep ? "on" : "off") : "";
  if (!r.ok) {
    std::printf("%-14s %6s %-9s %-5s %-8s failed: %s\n", scene.c_str(), bodies.c_str(), length.c_str(), sleep,
                engine_name(engine), r.error);
    return;
  }
  char ratio_text[16] = "";
  if (ratio) std::snprintf(ratio_text, sizeof ratio_text, "%.2f", *ratio);
  std::printf("%-14s %6s %-9s %-5s %-8s %8.3f %8.3f %8.3f %6s %9s %9s %9s %6d %5d %8.1f\n", scene.c_str(),
              bodies.c_str(), length.c_str(), sleep, engine_name(engine), r.median_ms, r.p90_ms, r.max_ms, ratio_text,
              metres(r.top_drift).c_str(), metres(r.any_drift).c_str(), asleep_text(run, r).c_str(), r.moving, r.sunk,
              m.peak_mib);
}

struct Outcome {
  Run run;
  Measured impulse, bullet;
  bool both_ok() const { return impulse.result.ok && bullet.result.ok; }
  double ratio() const { return impulse.result.median_ms / bullet.result.median_ms; }
};

const char* stack_verdict(const RunResult& r) {
  const double drift = std::max(r.top_drift, r.any_drift);
  if (drift < 0.01) return "holds";
  if (drift < 0.5) return "creeps";
  return "falls";
}

// The issue asks the 5050-box pyramid only to stand its 500 steps: 100 rows of soft contacts
// sink its top by centimetres. Standing: nothing moved a tenth of a box, nothing moves at the end.
bool stands(const RunResult& r) { return std::max(r.top_drift, r.any_drift) < 0.1 && r.moving == 0; }

const Outcome* find(const std::vector<Outcome>& outcomes, const std::string& scene, bool sleep) {
  for (const Outcome& o : outcomes)
    if (o.run.scene == scene && o.run.sleep == sleep && o.both_ok()) return &o;
  return nullptr;
}

void print_goals(const std::vector<Outcome>& outcomes) {
  std::printf("\nGoal 1: impulse's median ms/step <= 0.8x Bullet's, sleeping off\n");
  for (const char* scene : {"boxes", "spheres", "pyramid", "large-pyramid"}) {
    const Outcome* o = find(outcomes, scene, false);
    if (!o) continue;
    std::printf("  %-14s %-9s impulse %8.3f  Bullet %8.3f  ratio %5.2f  %s\n", scene, run_length(o->run.steps).c_str(),
                o->impulse.result.median_ms, o->bullet.result.median_ms, o->ratio(), o->ratio() <= 0.8 ? "met" : "MISSED");
  }
  std::printf("\nGoal 2: impulse's stacks hold (largest drift < 1 cm; the large pyramid 'stands': < 10 cm and\n"
              "nothing moving at the end; 'falls': > 50 cm) where Bullet's fall\n");
  for (const Outcome& o : outcomes) {
    if (!o.both_ok() || o.impulse.result.top_drift < 0) continue;
    const bool large = o.run.scene == "large-pyramid";
    const char* i = large && stands(o.impulse.result) ? "stands" : stack_verdict(o.impulse.result);
    const char* b = large && stands(o.bullet.result) ? "stands" : stack_verdict(o.bullet.result);
    std::printf("  %-14s %-9s sleep %-3s  impulse %-6s (%.4f m)  Bullet %-6s (%.4f m)  %s\n", o.run.scene.c_str(),
                run_length(o.run.steps).c_str(), o.run.sleep ? "on" : "off", i,
                std::max(o.impulse.result.top_drift, o.impulse.result.any_drift), b,
                std::max(o.bullet.result.top_drift, o.bullet.result.any_drift),
                std::strcmp(i, "holds") == 0 || std::strcmp(i, "stands") == 0 ? "met" : "MISSED");
  }
}

void print_growth(const std::vector<Outcome>& outcomes) {
  struct Point { const char* scene; int bodies; const Outcome* o; };
  std::vector<Point> points;
  for (auto [scene, bodies] : {std::pair{"pyramid", 210}, {"boxes", 1000}, {"large-pyramid", 5050}})
    if (const Outcome* o = find(outcomes, scene, false)) points.push_back({scene, bodies, o});
  if (points.empty()) return;
  std::printf("\nGrowth, sleeping off, median ms/step (us per body):\n");
  for (EngineId e : {EngineId::impulse, EngineId::bullet}) {
    std::printf("  %-8s", engine_name(e));
    for (size_t k = 0; k < points.size(); ++k) {
      const double ms = (e == EngineId::impulse ? points[k].o->impulse : points[k].o->bullet).result.median_ms;
      std::printf("%s%d %s %.3f (%.2f)", k ? "  ->  " : "", points[k].bodies, points[k].scene, ms, 1000 * ms / points[k].bodies);
    }
    if (points.size() >= 2) {
      const auto& a = points.front();
      const auto& b = points.back();
      const double ta = (e == EngineId::impulse ? a.o->impulse : a.o->bullet).result.median_ms;
      const double tb = (e == EngineId::impulse ? b.o->impulse : b.o->bullet).result.median_ms;
      std::printf("   [x%.1f bodies: x%.1f time, ~n^%.2f]", double(b.bodies) / a.bodies, tb / ta,
                  std::log(tb / ta) / std::log(double(b.bodies) / a.bodies));
    }
    std::printf("\n");
  }
  std::printf("  %-8s", "ratio");
  for (size_t k = 0; k < points.size(); ++k) std::printf("%s%d %.2f", k ? "  ->  " : "", points[k].bodies, points[k].o->ratio());
  std::printf("\n");
}

int usage(const char* program, FILE* to) {
  std::fprintf(to,
               "usage: %s [--quick] [--scene NAME]...\n"
               "  --quick        every run cut to 30 steps (large-pyramid: 5), for a smoke test\n"
               "  --scene NAME   only this scene (repeatable): stack-10, stack-20, pyramid, large-pyramid, boxes, spheres\n"
               "The default is the whole table of ../shared/bench/SCENES.md; it takes several minutes.\n",
               program);
  return to == stderr ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::set<std::string> only;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick") quick = true;
    else if (arg == "--scene" && i + 1 < argc) {
      std::string name = argv[++i];
      for (char& c : name)
        if (c == ' ' || c == '_') c = '-';
      try {
        make_scene(name);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "physics_bench: %s\n", e.what());
        return usage(argv[0], stderr);
      }
      only.insert(name);
    } else if (arg == "-h" || arg == "--help") return usage(argv[0], stdout);
    else return usage(argv[0], stderr);
  }

  std::vector<Run> runs;
  std::set<std::tuple<std::string, int, bool>> seen;
  for (Run run : full_runs()) {
    if (!only.empty() && !only.count(run.scene)) continue;
    if (quick) run.steps = std::min(run.steps, run.scene == "large-pyramid" ? 5 : 30);
    if (!seen.insert({run.scene, run.steps, run.sleep}).second) continue;  // --quick: pyramid 10 s = 60 s
    runs.push_back(run);
  }

  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  std::printf("physics_bench%s: impulse vs Bullet, scenes of ../shared/bench/SCENES.md\n", quick ? " --quick" : "");
  std::printf("date %s; %ld cores (nproc), CPU %s; load average %s at start\n", now_utc().c_str(), cores,
              first_line_of("/proc/cpuinfo", "model name").c_str(), load_average().c_str());
  std::printf("%s; %s; build %s, %s\n", impulse_description().c_str(), bullet_description().c_str(),
              IMPULSE_BUILD_TYPE, __VERSION__);
  std::printf("every body: unit mass, friction %.1f, restitution %.1f; 60 Hz fixed step; gravity 9.81 m/s^2\n",
              kFriction, kRestitution);
  const Measured empty = in_child([](RunResult& r) { r.ok = true; });
  std::printf("peak MiB: each run's own forked child (ru_maxrss); a child that does nothing: %.1f MiB\n\n", empty.peak_mib);

  print_header();
  std::vector<Outcome> outcomes;
  bool failed = false;
  const bool progress = isatty(2);
  for (size_t k = 0; k < runs.size(); ++k) {
    const Run& run = runs[k];
    Outcome o{run, {}, {}};
    for (EngineId e : {EngineId::impulse, EngineId::bullet}) {
      if (progress)
        std::fprintf(stderr, "\r[%zu/%zu] %s %s sleep %s: %s ...        ", k + 1, runs.size(), run.scene.c_str(),
                     run_length(run.steps).c_str(), run.sleep ? "on" : "off", engine_name(e));
      Measured m = in_child([&](RunResult& r) {
        const Scene scene = make_scene(run.scene);
        if (e == EngineId::impulse) run_impulse(scene, run, r);
        else run_bullet(scene, run, r);
      });
      failed = failed || !m.result.ok;
      (e == EngineId::impulse ? o.impulse : o.bullet) = m;
    }
    if (progress) std::fprintf(stderr, "\r%70s\r", "");
    print_row(run, EngineId::impulse, o.impulse, o.both_ok() ? std::optional<double>(o.ratio()) : std::nullopt);
    print_row(run, EngineId::bullet, o.bullet, std::nullopt);
    std::fflush(stdout);
    outcomes.push_back(o);
  }
  std::printf("\nratio i/B: impulse's median / Bullet's; drift: largest displacement from the start (top box; any box);\n"
              "moving: faster than 5 cm/s at the end; sunk: centre below the ground's top at the end; * not in SCENES.md\n");
  print_goals(outcomes);
  print_growth(outcomes);
  std::printf("\nload average %s at the end\n", load_average().c_str());
  return failed ? 1 : 0;
}
