// A student's AddCollisionImpulse written in Python (listing 1 as a function of the two bodies,
// the point, the normal and the depth) as a world's response, and impulse.grade over it: the
// physics' outside-response seam (physics/outside_response.h), with the call made in this process
// under the GIL. An exception the function raises fails the run, or the grade's case, with its
// words; it never takes the interpreter down. Ctrl-C stops the run.
#include "binding.h"

#include "demos/grade/grade.h"
#include "demos/grade/grade_report.h"
#include "physics/outside_response.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>

namespace impulse::python {
namespace {

thread_local double current_time_step = 0;  // s: listing 1's TimeStep() during a call

// A Python object that may be copied and dropped without the GIL (a scene's settings are copied
// on the film's threads): only the last owner's release takes the GIL.
struct HeldObject {
  py::object object;
  explicit HeldObject(py::object o) : object(std::move(o)) {}
  ~HeldObject() {
    py::gil_scoped_acquire gil;
    object = py::object();
  }
};

py::array_t<double> vec3(const std::array<float, 3>& v) { return py::array_t<double>(3, std::array<double, 3>{v[0], v[1], v[2]}.data()); }

py::array_t<double> matrix(const std::array<float, 9>& m) {
  std::array<double, 9> values;
  std::copy(m.begin(), m.end(), values.begin());
  return py::array_t<double>({3, 3}, values.data());
}

// A RigidBody of impulse.workshop (listing 1's members, snake_case) for the function to change.
py::object to_python(py::handle rigid_body, const physics::PlainBody& body) {
  return rigid_body(py::arg("centre") = vec3(body.centre), py::arg("inv_mass") = double(body.inv_mass),
                    py::arg("lin_velocity") = vec3(body.lin_velocity), py::arg("forces") = vec3(body.forces),
                    py::arg("inv_inertia") = matrix(body.inv_inertia), py::arg("ang_velocity") = vec3(body.ang_velocity),
                    py::arg("orientation") = py::array_t<double>(4, std::array<double, 4>{body.orientation[0], body.orientation[1],
                                                                                          body.orientation[2], body.orientation[3]}.data()),
                    py::arg("torques") = vec3(body.torques), py::arg("world_inv_inertia") = matrix(body.world_inv_inertia),
                    py::arg("restitution") = double(body.restitution), py::arg("friction") = double(body.friction));
}

// The velocity the function left in `name`, three numbers.
std::array<float, 3> read_back(const py::object& body, const char* name, const std::string& who) {
  py::array_t<double, py::array::c_style | py::array::forcecast> values;
  try {
    values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(body.attr(name));
  } catch (const py::error_already_set&) {
  }
  if (!values || values.size() != 3)
    throw physics::ResponseFailure(who + " left " + name + " as " + std::string(py::repr(body.attr(name))) +
                                   ", not three numbers (a vector like numpy.array([x, y, z]))");
  return {float(values.at(0)), float(values.at(1)), float(values.at(2))};
}

class PythonResponse : public physics::OutsideResponse {
 public:
  explicit PythonResponse(std::shared_ptr<HeldObject> function) : function_(std::move(function)) {}
  ~PythonResponse() override = default;

  void respond(physics::PlainBody& a, physics::PlainBody& b, const physics::PlainContact& contact) override {
    py::gil_scoped_acquire gil;
    const py::object& function = function_->object;
    const std::string who = py::hasattr(function, "__name__") ? function.attr("__name__").cast<std::string>() + "()" : "the response";
    try {
      static const py::handle rigid_body = py::object(py::module_::import("impulse.workshop").attr("RigidBody")).release();  // kept for the process
      py::object body_a = to_python(rigid_body, a), body_b = to_python(rigid_body, b);
      current_time_step = contact.time_step;
      function(body_a, body_b, vec3(contact.point), vec3(contact.normal), double(contact.penetration));
      a.lin_velocity = read_back(body_a, "lin_velocity", who);
      a.ang_velocity = read_back(body_a, "ang_velocity", who);
      b.lin_velocity = read_back(body_b, "lin_velocity", who);
      b.ang_velocity = read_back(body_b, "ang_velocity", who);
    } catch (py::error_already_set& error) {
      if (error.matches(PyExc_KeyboardInterrupt) || error.matches(PyExc_SystemExit)) throw;  // stops the run: not the function's fault
      throw physics::ResponseFailure(who + " raised " + error.what());
    }
  }

 private:
  std::shared_ptr<HeldObject> function_;
};

py::dict case_dict(const workshop::CaseResult& result) {
  py::dict item;
  item["name"] = result.name;
  item["title"] = result.title;
  item["law"] = result.law;
  item["expected"] = result.expected;
  item["measured"] = result.measured;
  item["passed"] = result.passed;
  item["hint"] = result.hint;
  item["failure"] = result.failure;
  return item;
}

workshop::CaseResult case_result(const py::dict& item) {
  workshop::CaseResult result;
  result.name = item["name"].cast<std::string>();
  result.title = item["title"].cast<std::string>();
  result.law = item["law"].cast<std::string>();
  result.expected = item["expected"].cast<std::string>();
  result.measured = item["measured"].cast<std::string>();
  result.passed = item["passed"].cast<bool>();
  result.hint = item["hint"].cast<std::string>();
  result.failure = item["failure"].cast<std::string>();
  return result;
}

physics::OutsideResponseMaker maker_of(const py::object& function) {
  if (function.is_none()) return {};  // the engine's reference
  if (!PyCallable_Check(function.ptr()))
    throw std::invalid_argument("a response is a function of (c0, c1, hit_point, normal, penetration), got " +
                                std::string(py::repr(function)));
  auto held = std::make_shared<HeldObject>(function);
  return [held] { return std::make_unique<PythonResponse>(held); };
}

}  // namespace

void set_python_response(demos::Scene& scene, const py::object& function) {
  if (scene.world.method != physics::ResponseMethod::workshop && scene.world.method != physics::ResponseMethod::impulse)
    throw std::invalid_argument("a response takes the place of listing 1's page, so it runs with the workshop method; "
                                "this scene sets another (world.method)");
  scene.world.method = physics::ResponseMethod::workshop;
  scene.world.reference_listing = false;
  scene.world.printed_eq8_sign = false;
  scene.world.response = maker_of(function);
}

// The text of the function's file as far as Python knows it, its lines where the file has them
// (grade's hints name them); "" where Python cannot tell (a lambda typed at a prompt).
std::string source_of(const py::object& function) {
  try {
    const py::tuple found = py::module_::import("inspect").attr("getsourcelines")(function);
    std::string text(size_t(std::max(0, found[1].cast<int>() - 1)), '\n');
    for (const py::handle line : found[0].cast<py::list>()) text += line.cast<std::string>();
    return text;
  } catch (const py::error_already_set&) {
    return "";
  }
}

void add_response_bindings(py::module_& module) {
  module.def("time_step", [] { return current_time_step; });
  module.def("case_names", &workshop::case_names);
  module.def(
      "grade",
      [](py::object function, const std::string& only, py::object progress) {
        const physics::OutsideResponseMaker maker = maker_of(function);
        const std::string source = source_of(function);
        std::vector<workshop::CaseResult> results;
        const std::vector<std::string> names = only.empty() ? workshop::case_names() : std::vector<std::string>{only};
        PythonProgress report(std::move(progress));
        {
          py::gil_scoped_release released;
          for (const std::string& name : names) {
            results.push_back(workshop::grade_case(name, maker, source));
            report(long(results.size()), long(names.size()));
          }
        }
        py::list list;
        for (const workshop::CaseResult& result : results) list.append(case_dict(result));
        return list;
      },
      py::arg("function"), py::arg("only") = "", py::arg("progress") = py::none());
  module.def("grade_table", [](const std::string& name, const py::list& cases) {
    std::vector<workshop::CaseResult> results;
    for (py::handle item : cases) results.push_back(case_result(item.cast<py::dict>()));
    return workshop::grade_table(name, results);
  });
  module.def("grade_json", [](const std::string& name, const py::list& cases) {
    std::vector<workshop::CaseResult> results;
    for (py::handle item : cases) results.push_back(case_result(item.cast<py::dict>()));
    return workshop::grade_json(name, results);
  });
  module.def("failure_videos", [](const std::string& directory, const std::string& name, py::object function, const py::list& cases) {
    std::vector<workshop::CaseResult> results;
    for (py::handle item : cases) results.push_back(case_result(item.cast<py::dict>()));
    const physics::OutsideResponseMaker maker = maker_of(function);
    py::gil_scoped_release released;
    return workshop::write_failure_videos(directory, name, maker, results, false);
  });
}

}  // namespace impulse::python
