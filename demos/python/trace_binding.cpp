// Scene.simulate for Python: the numbers `impulse simulate` writes, as numpy arrays of the same
// doubles (demos/simulate.h's trace_scene, with a sink that keeps them instead of printing them).
#include "binding.h"

#include "demos/simulate.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

namespace impulse::python {
namespace {

// Each kept step's rows, in columns.
class ArraySink : public demos::TraceSink {
 public:
  std::vector<double> time;
  std::vector<int64_t> step;
  std::vector<double> bodies;  // per kept step, per body: x y z, qw qx qy qz, vx vy vz, wx wy wz
  std::vector<double> world;   // per kept step: kinetic, potential energy, p (3), L (3)
  std::vector<int64_t> contact_row, contact_a, contact_b;  // the kept step's index; bodies, -1 for none
  std::vector<double> contact_values;  // per contact: point (3), normal (3), depth, normal impulse, friction (3)
  size_t body_count = 0;
  size_t expected_rows = 0;
  bool keep_contacts = true;  // reserved at the first row: growing 75 MB (the 1000-box heap) by doubling costs 15 %

  void rows(long step_number, const physics::World& w) override {
    const physics::StepRecord& record = w.record();
    body_count = w.bodies().size();
    if (time.empty()) {
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
      bodies.insert(bodies.end(), std::begin(values), std::end(values));
    }
    const double totals[] = {record.kinetic_energy,      record.potential_energy,    record.linear_momentum.x(),
                             record.linear_momentum.y(), record.linear_momentum.z(), record.angular_momentum.x(),
                             record.angular_momentum.y(), record.angular_momentum.z()};
    world.insert(world.end(), std::begin(totals), std::end(totals));
    if (step_number > 0 && keep_contacts) {
      for (const physics::ContactRecord& c : record.contacts) {
        contact_row.push_back(int64_t(time.size()));
        contact_a.push_back(c.body_a);
        contact_b.push_back(c.body_b);
        const double values[] = {c.point.x(),  c.point.y(),  c.point.z(),         c.normal.x(),
                                 c.normal.y(), c.normal.z(), c.penetration,       c.normal_impulse,
                                 c.tangent_impulse.x(), c.tangent_impulse.y(), c.tangent_impulse.z()};
        contact_values.insert(contact_values.end(), std::begin(values), std::end(values));
      }
    }
    time.push_back(record.time);
    step.push_back(step_number);
  }
};

// A vector's numbers as an array of `shape`, owning them (no copy).
template <class T>
py::array_t<T> to_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free(owned, [](void* pointer) { delete static_cast<std::vector<T>*>(pointer); });
  return py::array_t<T>(shape, owned->data(), free);
}

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
        trace["time"] = to_array(std::move(sink.time), {rows});
        trace["step"] = to_array(std::move(sink.step), {rows});
        trace["bodies"] = to_array(std::move(sink.bodies), {rows, bodies, 13});
        trace["world"] = to_array(std::move(sink.world), {rows, 8});
        trace["contact_row"] = to_array(std::move(sink.contact_row), {contact_count});
        trace["contact_a"] = to_array(std::move(sink.contact_a), {contact_count});
        trace["contact_b"] = to_array(std::move(sink.contact_b), {contact_count});
        trace["contact_values"] = to_array(std::move(sink.contact_values), {contact_count, 11});
        trace["checks"] = check_list(checks);
        return trace;
      },
      py::arg("scene"), py::arg("duration") = -1.0, py::arg("every") = 1, py::arg("contacts") = true,
      py::arg("progress") = py::none());
}

}  // namespace impulse::python
