// rbcstab.fit: the inverse problem (inverse/fit.hpp), the same call as `rbcstab fit`.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rbcstab/inverse/fit.hpp"

namespace rbcstab::python {

namespace {
py::tuple fit_data(const std::string& data, const std::vector<std::string>& free, const std::string& fixed, int starts,
                   int max_iterations, unsigned seed, bool profiles, int profile_points, double profile_span) {
  FitOptions o;
  o.profiles.enabled = profiles;
  o.profiles.points = profile_points;
  o.profiles.span = profile_span;
  o.starts = starts;
  o.max_iterations = max_iterations;
  o.seed = seed;
  FitResult r;
  nlohmann::json doc;
  {
    py::gil_scoped_release release;
    const ObservationData observations = read_observation_data(data);
    CellModel cell;
    apply_assignments(cell, fixed, "fixed");
    r = fit(observations, free, cell, o);
    doc = to_json(r);
    doc["data"] = data;
  }
  return py::make_tuple(to_python(doc), fit_text(r));
}
}  // namespace

void bind_inverse(py::module_& m) {
  m.def("fit", &fit_data, py::arg("data"), py::arg("free"), py::arg("fixed"), py::arg("starts"),
        py::arg("max_iterations"), py::arg("seed"), py::arg("profiles"), py::arg("profile_points"),
        py::arg("profile_span"),
        "(json dict, text): rbcstab fit --data DATA --free FREE --fixed FIXED [--profiles] --json and its text.");
}

}  // namespace rbcstab::python
