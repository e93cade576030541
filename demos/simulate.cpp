#include "demos/simulate.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>

#include "demos/scene/scene_world.h"
#include "render/part_file.h"

namespace impulse::demos {
namespace {

// A CSV file written to its own temporary and renamed when complete (render/part_file.h).
class CsvFile {
 public:
  CsvFile(const std::string& path, const char* header) : part_(path), file_(std::fopen(part_.part_path().c_str(), "w")) {
    if (!file_) throw render::OutputError("cannot open " + part_.part_path() + " for writing: " + std::strerror(errno));
    std::fputs(header, file_.get());
  }
  std::FILE* get() { return file_.get(); }
  void commit() {
    if (std::fflush(file_.get()) != 0 || std::ferror(file_.get()) || std::fclose(file_.release()) != 0)
      throw render::OutputError("cannot write " + part_.part_path() + ": " + std::strerror(errno));
    part_.commit();
  }

 private:
  struct Close {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  render::PartFile part_;
  std::unique_ptr<std::FILE, Close> file_;
};

std::optional<CsvFile> open_csv(const std::string& path, const char* header) {
  if (path.empty()) return std::nullopt;
  return std::optional<CsvFile>(std::in_place, path, header);
}

// Body names may hold commas or quotes: CSV quotes them.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The CSV files of `impulse simulate`: each row as "%.9g" of the double the world holds.
class CsvSink : public TraceSink {
 public:
  explicit CsvSink(const TraceOptions& options)
      : bodies_(open_csv(options.bodies_path,
                         "time_s,step,body,x_m,y_m,z_m,qw,qx,qy,qz,vx_m_per_s,vy_m_per_s,vz_m_per_s,wx_rad_per_s,"
                         "wy_rad_per_s,wz_rad_per_s\n")),
        contacts_(open_csv(options.contacts_path,
                           "time_s,step,body_a,body_b,x_m,y_m,z_m,nx,ny,nz,penetration_m,normal_impulse_N_s,friction_x_N_s,"
                           "friction_y_N_s,friction_z_N_s\n")),
        world_(open_csv(options.world_path,
                        "time_s,step,kinetic_energy_J,potential_energy_J,px_kg_m_per_s,py_kg_m_per_s,pz_kg_m_per_s,"
                        "Lx_kg_m2_per_s,Ly_kg_m2_per_s,Lz_kg_m2_per_s\n")) {}

  void rows(long step, const physics::World& world) override {
    const physics::StepRecord& record = world.record();
    const double t = record.time;
    auto name_of = [&](int body) { return body >= 0 ? quoted(world.bodies()[body].name) : std::string("world"); };
    if (bodies_) {
      for (const physics::Body& b : world.bodies()) {
        std::fprintf(bodies_->get(), "%.9g,%ld,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", t,
                     step, quoted(b.name).c_str(), b.position.x(), b.position.y(), b.position.z(), b.orientation.w(),
                     b.orientation.x(), b.orientation.y(), b.orientation.z(), b.velocity.x(), b.velocity.y(),
                     b.velocity.z(), b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z());
      }
    }
    if (contacts_ && step > 0) {
      for (const physics::ContactRecord& c : record.contacts) {
        std::fprintf(contacts_->get(), "%.9g,%ld,%s,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", t, step,
                     name_of(c.body_a).c_str(), name_of(c.body_b).c_str(), c.point.x(), c.point.y(), c.point.z(),
                     c.normal.x(), c.normal.y(), c.normal.z(), c.penetration, c.normal_impulse, c.tangent_impulse.x(),
                     c.tangent_impulse.y(), c.tangent_impulse.z());
      }
    }
    if (world_) {
      std::fprintf(world_->get(), "%.9g,%ld,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", t, step, record.kinetic_energy,
                   record.potential_energy, record.linear_momentum.x(), record.linear_momentum.y(),
                   record.linear_momentum.z(), record.angular_momentum.x(), record.angular_momentum.y(),
                   record.angular_momentum.z());
    }
  }

  void commit() {
    for (std::optional<CsvFile>* file : {&bodies_, &contacts_, &world_})
      if (*file) (*file)->commit();
  }

 private:
  std::optional<CsvFile> bodies_, contacts_, world_;
};

}  // namespace

long trace_scene(const Scene& scene, double duration, int every, TraceSink& sink, std::vector<CheckResult>* checks,
                 const std::function<void(long done, long total)>& progress) {
  physics::World world = build_world(scene);
  CheckWatch watch(scene.checks);
  watch.start(world);
  if (duration < 0) duration = scene.duration;
  every = std::max(every, 1);
  const double dt = scene.world.time_step;
  const long total = std::max(0L, long(std::ceil(duration / dt - 0.5)));
  sink.rows(0, world);
  long steps = 0;
  while (world.time() < duration - 0.5 * dt) {
    world.step();
    watch.step(world);
    ++steps;
    const bool last = !(world.time() < duration - 0.5 * dt);
    if (steps % every == 0 || last) sink.rows(steps, world);
    if (progress) progress(steps, std::max(total, steps));
  }
  if (checks) *checks = watch.results();
  return steps;
}

long simulate_scene(const Scene& scene, const TraceOptions& options, std::vector<CheckResult>* checks) {
  CsvSink sink(options);
  const long steps = trace_scene(scene, options.duration, options.every, sink, checks);
  sink.commit();
  return steps;
}

}  // namespace impulse::demos
