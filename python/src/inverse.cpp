// rbcstab.fit: the inverse problem (inverse/fit.hpp), the same call as `rbcstab fit`, with its page
// (report/fit_page.hpp) when asked. Ctrl-C stops the fit within an Ipopt iteration and raises KeyboardInterrupt;
// progress counts the starts and profile points done.
#include <pybind11/stl.h>

#include <atomic>
#include <optional>

#include "bindings.hpp"
#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/report/fit_page.hpp"

namespace rbcstab::python {

namespace {
py::tuple fit_data(const std::string& data, const std::vector<std::string>& free, const std::string& fixed, int starts,
                   int max_iterations, unsigned seed, bool profiles, int profile_points, double profile_span,
                   const std::string& report, bool overwrite, const std::string& jacobian, bool regime_constraints,
                   const std::string& profile_method, const py::object& progress) {
  FitOptions o;
  o.jacobian = from_string<JacobianMethod>(jacobian, "jacobian");
  o.profiles.method = from_string<ProfileMethod>(profile_method, "profile_method");
  o.regime_constraints = regime_constraints;
  o.profiles.enabled = profiles;
  o.profiles.points = profile_points;
  o.profiles.span = profile_span;
  o.starts = starts;
  o.max_iterations = max_iterations;
  o.seed = seed;
  FitReportOptions ro;
  ro.output = report;
  ro.overwrite = overwrite;
  std::atomic<bool> stop{false};
  std::optional<py::error_already_set> pending;  // KeyboardInterrupt, or what the progress callable raised
  const PythonProgress bar(progress);
  const ProgressCallback count = bar.callback();
  const std::function<void()> poll = signal_poll();
  o.stop = &stop;
  o.on_progress = [&](const FitProgress& p) {
    if (pending) return;
    try {
      poll();
      // One count: starts, then profile points, whose number is not known in advance (total 0 then).
      if (count) count(p.starts_done + p.profile_points, profiles ? 0 : p.starts);
    } catch (py::error_already_set& e) {
      pending.emplace(std::move(e));
      stop.store(true);
    }
  };
  FitResult r;
  nlohmann::json doc;
  {
    py::gil_scoped_release release;
    const ObservationData observations = read_observation_data(data);
    CellModel cell;
    apply_assignments(cell, fixed, "fixed");
    if (!report.empty()) ro = check_fit_report(ro);  // before the fit: nothing computed for a folder refused
    r = fit(observations, free, cell, o);
    doc = to_json(r);
    doc["data"] = data;
    if (!pending && !report.empty() && r.status != FitStatus::failed && r.status != FitStatus::interrupted)
      doc["report"] = write_fit_report(r, observations, ro).output;
  }
  if (pending) throw std::move(*pending);
  bar.finish();
  return py::make_tuple(to_python(doc), fit_text(r));
}
}  // namespace

void bind_inverse(py::module_& m) {
  m.def("fit", &fit_data, py::arg("data"), py::arg("free"), py::arg("fixed"), py::arg("starts"),
        py::arg("max_iterations"), py::arg("seed"), py::arg("profiles"), py::arg("profile_points"),
        py::arg("profile_span"), py::arg("report") = "", py::arg("overwrite") = false,
        py::arg("jacobian") = "variational", py::arg("regime_constraints") = true,
        py::arg("profile_method") = "gauss_newton", py::arg("progress") = py::none(),
        "(json dict, text): rbcstab fit --data DATA --free FREE --fixed FIXED [--profiles] [--report DIR] --json and "
        "its text; progress(done, total, eta) counts the starts, then the profile points (total 0).");
}

}  // namespace rbcstab::python
