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
        // With a Python response the run calls it here, under the GIL.
        render::write_file(path, [&](std::ostream& out) { demos::write_page(core.scene, script, out); });
        return path;
      },
      py::arg("scene"), py::arg("path"));
}

}  // namespace impulse::python
