// Scenes for Python: read from a file with settings over it, or from the file's tables as dicts.
#include "binding.h"

#include "demos/film/live_equations.h"
#include "demos/scene/scene_error.h"
#include "demos/scene/scene_world.h"

#include <pybind11/stl.h>

namespace impulse::python {
namespace {

// A Python value as a TOML node: dicts are tables, lists arrays (of tables when they hold dicts),
// and True, 2, 0.5, "text" what they are. A numpy array or number goes through its tolist().
std::unique_ptr<toml::node> to_toml(py::handle given, const std::string& where) {
  py::object value = py::reinterpret_borrow<py::object>(given);
  if (py::hasattr(value, "tolist") && !py::isinstance<py::str>(value)) value = value.attr("tolist")();
  if (py::isinstance<py::bool_>(value)) return std::make_unique<toml::value<bool>>(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return std::make_unique<toml::value<int64_t>>(value.cast<int64_t>());
  if (py::isinstance<py::float_>(value)) return std::make_unique<toml::value<double>>(value.cast<double>());
  if (py::isinstance<py::str>(value)) return std::make_unique<toml::value<std::string>>(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    auto table = std::make_unique<toml::table>();
    for (auto [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key))
        throw demos::SceneError(where + ": the keys of a table are strings, got " + std::string(py::repr(key)));
      const std::string name = key.cast<std::string>();
      table->insert(name, std::move(*to_toml(item, where + "." + name)));
    }
    return table;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    auto array = std::make_unique<toml::array>();
    int index = 0;
    for (py::handle item : value) array->push_back(std::move(*to_toml(item, where + "[" + std::to_string(index++) + "]")));
    return array;
  }
  throw demos::SceneError(where + ": " + std::string(py::str(py::type::of(value).attr("__name__"))) +
                          " is not a scene value (give a bool, number, string, list or dict)");
}

}  // namespace

CoreScene read_scene(std::shared_ptr<const demos::SceneFile> file, std::vector<std::string> settings, py::object response) {
  CoreScene core{std::move(file), std::move(settings), {}, std::move(response)};
  core.scene = core.file->scene(core.settings);
  demos::check_equations(core.scene);  // a LaTeX error is the scene's, with its file and line, as on the command line
  for (const std::string& warning : demos::start_warnings(core.scene))
    PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1);
  if (!core.response.is_none()) set_python_response(core.scene, core.response);
  return core;
}

void add_scene_bindings(py::module_& module) {
  py::class_<CoreScene>(module, "CoreScene")
      .def_property_readonly("path", [](const CoreScene& core) { return core.scene.path; })
      .def_property_readonly("settings", [](const CoreScene& core) { return core.settings; })
      .def_property_readonly("title", [](const CoreScene& core) { return core.scene.title; })
      .def_property_readonly("duration", [](const CoreScene& core) { return core.scene.duration; })
      .def_property_readonly("time_step", [](const CoreScene& core) { return core.scene.world.time_step; })
      .def_property_readonly("response", [](const CoreScene& core) { return core.response; })
      .def_property_readonly("bodies",
                             [](const CoreScene& core) {
                               // As the world builds them (patterns expanded, a plane's name included).
                               std::vector<std::string> names;
                               for (const physics::BodyDef& body : core.scene.bodies) names.push_back(body.name);
                               return names;
                             })
      .def_property_readonly("compare",
                             [](const CoreScene& core) {
                               py::dict compare;
                               if (core.scene.compare.values.empty()) return py::object(py::none());
                               compare["key"] = core.scene.compare.key;
                               compare["values"] = core.scene.compare.values;
                               compare["labels"] = core.scene.compare.labels;
                               return py::object(compare);
                             })
      .def("with_settings",
           [](const CoreScene& core, std::vector<std::string> settings, py::object response) {
             std::vector<std::string> all = core.settings;
             all.insert(all.end(), settings.begin(), settings.end());
             return read_scene(core.file, std::move(all), response.is_none() ? core.response : response);
           },
           py::arg("settings"), py::arg("response") = py::none());

  module.def(
      "load",
      [](const std::string& path, std::vector<std::string> settings, py::object response) {
        return read_scene(std::make_shared<const demos::SceneFile>(path), std::move(settings), std::move(response));
      },
      py::arg("path"), py::arg("settings") = std::vector<std::string>{}, py::arg("response") = py::none());
  module.def(
      "from_tables",
      [](py::dict tables, const std::string& name, std::vector<std::string> settings, py::object response) {
        std::unique_ptr<toml::node> root = to_toml(tables, name);
        auto file = std::make_shared<const demos::SceneFile>(std::move(*root->as_table()), name);
        return read_scene(std::move(file), std::move(settings), std::move(response));
      },
      py::arg("tables"), py::arg("name"), py::arg("settings") = std::vector<std::string>{}, py::arg("response") = py::none());
}

}  // namespace impulse::python
