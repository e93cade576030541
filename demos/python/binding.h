// What the parts of the Python module (_impulse) share: a scene as Python holds it, and the call
// back into Python that long work makes (progress, Ctrl-C).
#pragma once
#include "demos/scene/scene_file.h"

#include <pybind11/pybind11.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace impulse::python {

namespace py = pybind11;

// A scene read from its file (or from tables built in Python) with `settings` over it, and the
// Python function that answers its contacts, if one is set (response_binding.cpp).
struct CoreScene {
  std::shared_ptr<const demos::SceneFile> file;
  std::vector<std::string> settings;  // KEY=VALUE, as --set takes them
  demos::Scene scene;
  py::object response;  // None, or listing 1 as a Python function
};

// Reads the scene of `file` with `settings` and `response` (None for the scene's own).
CoreScene read_scene(std::shared_ptr<const demos::SceneFile> file, std::vector<std::string> settings, py::object response);

// Calls a Python `progress(done, total)` (None: nothing) at most ten times a second and at the
// end, from a thread that does not hold the GIL. Each call first looks for a signal: Ctrl-C
// throws py::error_already_set (KeyboardInterrupt), which unwinds the work that called it, its
// temporaries deleted as on any failure.
class PythonProgress {
 public:
  explicit PythonProgress(py::object callback) : callback_(std::move(callback)) {}
  void operator()(long done, long total);

 private:
  py::object callback_;
  std::chrono::steady_clock::time_point last_{};
};

// A scene's [[check]] results as a list of dicts: check, passed, measured.
py::list check_list(const std::vector<demos::CheckResult>& results);

// Sets a Python function of listing 1's arguments as the world's response (workshop method).
void set_python_response(demos::Scene& scene, const py::object& function);

// Every pane the first's camera, video, playback and duration (as `impulse compare` does).
void share_first(std::vector<demos::Scene>& scenes);
// The scene's panes as `impulse render` and `impulse export` show them: its [compare]'s (each with
// the Python response, if any), `labels` theirs; or the scene alone.
std::vector<demos::Scene> scene_panes(const CoreScene& core, std::vector<std::string>& labels);

void add_scene_bindings(py::module_& module);
void add_trace_bindings(py::module_& module);
void add_film_bindings(py::module_& module);
void add_response_bindings(py::module_& module);
void add_page_bindings(py::module_& module);

}  // namespace impulse::python
