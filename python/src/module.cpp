// The compiled half of the rbcstab Python package (python/rbcstab/__init__.py is the other): library errors
// become Python exceptions, then each source file adds its bindings.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/report/report.hpp"

PYBIND11_MODULE(_rbcstab, m) {
  namespace py = pybind11;
  m.doc() = "rbcstab's C++ library (use the rbcstab package, not this module)";
  m.attr("__version__") = RBCSTAB_VERSION;
  // Invalid input names the parameter, its value and the allowed range: ValueError, as for any Python API, in
  // Python's words (keywords, not the CLI's flags).
  // An output that cannot be written is an OSError; anything else the library throws is a RuntimeError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const rbcstab::InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, rbcstab::python::python_words(e.what()).c_str());
    } catch (const rbcstab::OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });
  m.def(
      "report_script_dir", [] { return rbcstab::find_script_dir(""); },
      "The folder of the report's drawing code (rbcstab_report.py, phase_draw.py, bifurcation_draw.py), as the "
      "CLI finds it; '' when it cannot be found.");
  rbcstab::python::bind_scene(m);
  rbcstab::python::bind_runs(m);
  rbcstab::python::bind_model(m);
  rbcstab::python::bind_continuation(m);
  rbcstab::python::bind_sweep(m);
  rbcstab::python::bind_inverse(m);
}
