// A scene's interactive page from Python (Scene.view): `impulse export`'s HTML, written where asked.
#include "binding.h"

#include "demos/page/page_export.h"
#include "render/part_file.h"

namespace impulse::python {

void add_page_bindings(py::module_& module) {
  module.def(
      "page",
      [](const CoreScene& core, const std::string& path) {
        const std::string script = demos::page_script();
        std::vector<std::string> labels;
        const std::vector<demos::Scene> scenes = scene_panes(core, labels);  // a [compare]'s panes, as export's
        std::vector<demos::Pane> panes;
        for (size_t i = 0; i < scenes.size(); ++i) panes.push_back({&scenes[i], labels[i]});
        // With a Python response the run calls it here, under the GIL.
        render::write_file(path, [&](std::ostream& out) { demos::write_page(panes, script, out); });
        return path;
      },
      py::arg("scene"), py::arg("path"));
}

}  // namespace impulse::python
