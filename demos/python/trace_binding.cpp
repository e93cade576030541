// Scene.simulate for Python: the numbers `impulse simulate` writes, as numpy arrays of the same
// doubles (demos/simulate.h's trace_scene, with a sink that keeps them instead of printing them).
#include "binding.h"

#include "demos/simulate.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

namespace impulse::python {
namespace {

// A growing column of numbers in memory of its own, handed to numpy without a copy. It grows by
// mremap, which moves pages instead of copying them: a std::vector's copies of the 1000-box heap's
// contacts (320 MB over 12 s) cost a tenth of the run. (Huge pages, asked for with madvise, cost
// far more: the kernel compacts memory for them on the fault, 40 s here.)
template <class T>
class Column {
 public:
  Column() = default;
  Column(const Column&) = delete;
  Column& operator=(const Column&) = delete;
  ~Column() {
    if (data_) munmap(data_, capacity_ * sizeof(T));
  }

  void reserve(size_t count) {
    if (count > capacity_) grow(count);
  }
  void push_back(T value) { append(&value, 1); }
  template <size_t N>
  void append(const T (&values)[N]) { append(values, N); }
  size_t size() const { return size_; }

  // The numbers as an array of `shape`, which from now on owns them.
  py::array_t<T> release(std::vector<py::ssize_t> shape) {
    if (!data_) return py::array_t<T>(shape);
    struct Mapping {
      void* data;
      size_t bytes;
    };
    auto* mapping = new Mapping{data_, capacity_ * sizeof(T)};
    py::capsule owner(mapping, [](void* pointer) {
      auto* m = static_cast<Mapping*>(pointer);
      munmap(m->data, m->bytes);
      delete m;
    });
    py::array_t<T> array(shape, data_, owner);
    data_ = nullptr;
    size_ = capacity_ = 0;
    return array;
  }

 private:
  void append(const T* values, size_t count) {
    if (size_ + count > capacity_) grow(size_ + count);
    std::memcpy(data_ + size_, values, count * sizeof(T));
    size_ += count;
  }
  void grow(size_t count) {
    const size_t page = 4096;
    const size_t wanted = std::max({count, 2 * capacity_, size_t(1 << 16)});
    const size_t bytes = (wanted * sizeof(T) + page - 1) / page * page;
    void* memory = data_ ? mremap(data_, capacity_ * sizeof(T), bytes, MREMAP_MAYMOVE)
                         : mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<T*>(memory);
    capacity_ = bytes / sizeof(T);
  }

  T* data_ = nullptr;
  size_t size_ = 0, capacity_ = 0;
};

// Each kept step's rows, in columns.
class ArraySink : public demos::TraceSink {
 public:
  Column<double> time;
  Column<int64_t> step;
  Column<double> bodies;  // per kept step, per body: x y z, qw qx qy qz, vx vy vz, wx wy wz
  Column<double> world;   // per kept step: kinetic, potential energy, p (3), L (3)
  Column<int64_t> contact_row, contact_a, contact_b;  // the kept step's index; bodies, -1 for none
  Column<double> contact_values;  // per contact: point (3), normal (3), depth, normal impulse, friction (3)
  size_t body_count = 0;
  size_t expected_rows = 0;  // reserved at the first row
  bool keep_contacts = true;

  void rows(long step_number, const physics::World& w) override {
    const physics::StepRecord& record = w.record();
    body_count = w.bodies().size();
    if (time.size() == 0) {
      time.reserve(expected_rows);
      step.reserve(expected_rows);
      bodies.reserve(expected_rows * body_count * 13);
      world.reserve(expected_rows * 8);
    }
    for (const physics::Body& b : w.bodies()) {
      const double values[] = {b.position.x(),    b.position.y(),    b.position.z(),    b.orientation.w(),
                               b.orientation.x(), b.orientation.y(), b.orientation.z(), b.velocity.x(),
                               b.velocity.y(),    b.velocity.z(),    b.angular_velocity.x(), b.angular_velocity.y(),
                               b.angular_velocity.z()};
      bodies.append(values);
    }
    const double totals[] = {record.kinetic_energy,      record.potential_energy,    record.linear_momentum.x(),
                             record.linear_momentum.y(), record.linear_momentum.z(), record.angular_momentum.x(),
                             record.angular_momentum.y(), record.angular_momentum.z()};
    world.append(totals);
    if (step_number > 0 && keep_contacts) {
      for (const physics::ContactRecord& c : record.contacts) {
        contact_row.push_back(int64_t(time.size()));
        contact_a.push_back(c.body_a);
        contact_b.push_back(c.body_b);
        const double values[] = {c.point.x(),  c.point.y(),  c.point.z(),         c.normal.x(),
                                 c.normal.y(), c.normal.z(), c.penetration,       c.normal_impulse,
                                 c.tangent_impulse.x(), c.tangent_impulse.y(), c.tangent_impulse.z()};
        contact_values.append(values);
      }
    }
    time.push_back(record.time);
    step.push_back(step_number);
  }
};

}  // namespace

void add_trace_bindings(py::module_& module) {
  module.def(
      "simulate",
      [](const CoreScene& core, double duration, int every, bool contacts, py::object progress) {
        if (every < 1) throw std::invalid_argument("every must be 1 or more, got " + std::to_string(every));
        ArraySink sink;
        const double steps = std::ceil((duration < 0 ? core.scene.duration : duration) / core.scene.world.time_step);
        sink.expected_rows = size_t(std::max(0.0, steps)) / size_t(every) + 2;
        sink.keep_contacts = contacts;
        std::vector<demos::CheckResult> checks;
        {
          PythonProgress report(std::move(progress));
          py::gil_scoped_release released;
          demos::trace_scene(core.scene, duration, every, sink, &checks, [&](long done, long total) { report(done, total); });
        }
        const auto rows = py::ssize_t(sink.time.size());
        const auto bodies = py::ssize_t(sink.body_count);
        const auto contact_count = py::ssize_t(sink.contact_row.size());
        py::dict trace;
        trace["time"] = sink.time.release({rows});
        trace["step"] = sink.step.release({rows});
        trace["bodies"] = sink.bodies.release({rows, bodies, 13});
        trace["world"] = sink.world.release({rows, 8});
        trace["contact_row"] = sink.contact_row.release({contact_count});
        trace["contact_a"] = sink.contact_a.release({contact_count});
        trace["contact_b"] = sink.contact_b.release({contact_count});
        trace["contact_values"] = sink.contact_values.release({contact_count, 11});
        trace["checks"] = check_list(checks);
        return trace;
      },
      py::arg("scene"), py::arg("duration") = -1.0, py::arg("every") = 1, py::arg("contacts") = true,
      py::arg("progress") = py::none());
}

}  // namespace impulse::python
