// _impulse: the C++ half of the Python package `impulse` (impulse/__init__.py is the other). It
// wraps the program's own libraries: the scene room reads scenes, simulate.h traces them, the film
// room renders them, the workshop room grades a response. The GIL is released while they work.
#include "binding.h"

#include "demos/scene/scene_error.h"
#include "physics/outside_response.h"
#include "render/part_file.h"

namespace impulse::python {

void PythonProgress::operator()(long done, long total) {
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (!callback_.is_none()) callback_(done, total);
}

py::list check_list(const std::vector<demos::CheckResult>& results) {
  py::list list;
  for (const demos::CheckResult& check : results) {
    py::dict item;
    item["check"] = check.text;
    item["passed"] = check.passed;
    item["measured"] = check.measured;
    list.append(item);
  }
  return list;
}

}  // namespace impulse::python

PYBIND11_MODULE(_impulse, module) {
  namespace py = pybind11;
  using namespace impulse;
  module.doc() = "impulse's libraries for Python: use the package `impulse`, not this module";

  // Errors as Python's: a scene that cannot be used is a ValueError carrying its place; an output
  // that cannot be written an OSError; a response that failed a RuntimeError.
  static py::handle scene_error = py::exception<demos::SceneError>(module, "SceneError", PyExc_ValueError).release();
  static py::handle output_error = py::exception<render::OutputError>(module, "OutputError", PyExc_OSError).release();
  static py::handle response_error =
      py::exception<physics::ResponseFailure>(module, "ResponseError", PyExc_RuntimeError).release();
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const demos::SceneError& error) {
      const demos::ScenePlace& place = error.place();
      py::object value = py::reinterpret_borrow<py::object>(scene_error)(error.what());
      auto or_none = [](const std::string& text) { return text.empty() ? py::object(py::none()) : py::object(py::str(text)); };
      value.attr("file") = or_none(place.file);
      value.attr("line") = place.line > 0 ? py::object(py::int_(place.line)) : py::object(py::none());
      value.attr("table") = or_none(place.table);
      value.attr("field") = or_none(place.field);
      value.attr("setting") = or_none(place.setting);
      PyErr_SetObject(scene_error.ptr(), value.ptr());
    } catch (const render::OutputError& error) {
      PyErr_SetString(output_error.ptr(), error.what());
    } catch (const physics::ResponseFailure& error) {
      PyErr_SetString(response_error.ptr(), error.what());
    }
  });

  python::add_scene_bindings(module);
  python::add_trace_bindings(module);
  python::add_film_bindings(module);
  python::add_response_bindings(module);
  python::add_page_bindings(module);
}
