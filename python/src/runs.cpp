// One scene's runs, as the CLI's simulate, thresholds, post and summary: the same library calls, the same JSON
// serialisers (so a Python dict equals json.loads of the CLI's --json), the GIL released while they compute.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "bindings.hpp"
#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/simulation_io.hpp"
#include "rbcstab/verdict/certified_run.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

namespace rbcstab::python {

namespace {

// Every row of the output grid (Trajectory::rows), NaN where a certified early stop skipped it: t, sigma, r, Psi,
// integrated and Delta_l(t) as a (rows, L - 1) array, column l - 2.
void trajectory_arrays(const Trajectory& tr, int L, py::dict& arrays) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const py::ssize_t rows = py::ssize_t(tr.rows()), cols = L - 1;
  py::array_t<double> Delta({rows, cols}), t(rows), sigma(rows), r(rows), Psi(rows);
  py::array_t<bool> integrated(rows);
  auto D = Delta.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows; ++i) {
    const std::size_t row = std::size_t(i), k = tr.sample(row);
    const bool in = tr.integrated(row);
    t.mutable_data()[i] = tr.time(row);
    integrated.mutable_data()[i] = in;
    sigma.mutable_data()[i] = in ? tr.sigma[k] : nan;
    r.mutable_data()[i] = in ? tr.r[k] : nan;
    Psi.mutable_data()[i] = in ? tr.Psi[k] : nan;
    for (py::ssize_t j = 0; j < cols; ++j) D(i, j) = in ? tr.Delta_l[k][std::size_t(j)] : nan;
  }
  arrays["Delta"] = Delta;
  arrays["t"] = t;
  arrays["sigma"] = sigma;
  arrays["r"] = r;
  arrays["Psi"] = Psi;
  arrays["integrated"] = integrated;
}

// The scene with Ctrl-C wired into its integrator.
SceneFile interruptible(const py::handle& scene) {
  SceneFile f = scene_file(scene);
  f.options.integrator.poll = signal_poll();
  return f;
}

py::tuple simulate_file(const py::handle& scene, std::vector<double> t_eval, bool dense_output,
                        const py::object& progress) {
  SceneFile f = interruptible(scene);
  f.options.t_eval = std::move(t_eval);
  f.options.dense_output = dense_output;
  const PythonProgress time(progress);  // t of T, after every accepted step
  f.options.on_progress = time.callback();
  SimulationResult r;
  {
    py::gil_scoped_release release;
    r = simulate_scene(f, f.options);
  }
  time.finish();
  const nlohmann::json j = simulation_json(f, r);
  py::dict arrays;
  trajectory_arrays(r.trajectory, r.L, arrays);
  arrays["y_final"] = own(std::move(r.y_final));
  if (dense_output) arrays["dense"] = std::move(r.dense);
  return py::make_tuple(to_python(j), arrays, simulation_text(f, r));
}

py::tuple thresholds_scene(const py::handle& scene, bool exact_C_star) {
  SceneFile f = scene_file(scene);
  ThresholdReport t;
  {
    py::gil_scoped_release release;
    apply_truncation(f, TruncationUse::analysis);
    t = threshold_report(f.scene, exact_C_star);
  }
  return py::make_tuple(to_python(thresholds_json(f, t)), thresholds_text(f, t));
}

py::tuple post_scene(const py::handle& scene) {
  SceneFile f = interruptible(scene);
  PostRun p;
  {
    py::gil_scoped_release release;
    p = run_post(std::move(f));
  }
  return py::make_tuple(to_python(post_json(p.file, p.post, p.run)), post_text(p.file, p.post, p.run));
}

py::tuple summary_scene(const py::handle& scene) {
  SceneFile f = interruptible(scene);
  SummaryRun s;
  {
    py::gil_scoped_release release;
    s = run_summary(std::move(f));
  }
  return py::make_tuple(to_python(summary_json(s.file, s.run, s.prediction)),
                        summary_text(s.file, s.run, s.prediction));
}

// The same work as simulate_file without Python: the truncation, the run and its JSON, timed in C++ (seconds per
// repeat). benchmarks/python/python_overhead.py compares it with the Python call in one process.
std::vector<double> time_simulate_cpp(const py::handle& scene, int repeats) {
  if (repeats < 1) throw py::value_error("repeats = " + std::to_string(repeats) + " is out of range: must be >= 1");
  const SceneFile base = scene_file(scene);
  std::vector<double> seconds;
  py::gil_scoped_release release;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    SceneFile f = base;
    const SimulationResult r = simulate_scene(f, f.options);
    const nlohmann::json j = simulation_json(f, r);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (j.empty()) throw std::logic_error("empty JSON");
  }
  return seconds;
}

// DenseOutput at the times t (any shape): an array of shape t.shape + (columns,). ValueError for a time that is
// not finite or outside the run's [first, last] time.
py::array_t<double> dense_at(const DenseOutput& d, const py::array_t<double, py::array::forcecast>& t) {
  std::vector<py::ssize_t> shape(t.shape(), t.shape() + t.ndim());
  shape.push_back(py::ssize_t(d.columns()));
  py::array_t<double> out(shape);
  const double* in = t.data();
  double* o = out.mutable_data();
  const double lo = d.empty() ? 0.0 : d.t().front(), hi = d.empty() ? 0.0 : d.t().back();
  for (py::ssize_t k = 0; k < t.size(); ++k) {
    if (!(std::isfinite(in[k]) && in[k] >= lo && in[k] <= hi))
      throw py::value_error("t = " + format_value(in[k]) + " is out of range: must be finite and in [" +
                            format_value(lo) + ", " + format_value(hi) + "] (the run's span)");
    const std::vector<double> v = d(in[k]);
    std::copy(v.begin(), v.end(), o + k * py::ssize_t(d.columns()));
  }
  return out;
}

}  // namespace

void bind_runs(py::module_& m) {
  py::class_<DenseOutput>(m, "DenseOutput",
                          "The observables Delta_2..Delta_L, sigma, r, Psi (columns) at every accepted step of a run, "
                          "interpolated between them (degree 7 through the nearest steps); NaN in a certified skip.")
      .def("__call__", &dense_at, py::arg("t"))
      .def_property_readonly("columns", &DenseOutput::columns)
      .def(py::pickle(
          [](const DenseOutput& d) { return py::make_tuple(d.columns(), d.t(), d.values(), d.segment_starts()); },
          [](const py::tuple& s) {
            return DenseOutput(s[0].cast<std::size_t>(), s[1].cast<std::vector<double>>(),
                               s[2].cast<std::vector<double>>(), s[3].cast<std::vector<std::size_t>>());
          }));
  m.def("simulate", &simulate_file, py::arg("scene"), py::arg("t_eval") = std::vector<double>{},
        py::arg("dense_output") = false, py::arg("progress") = py::none(),
        "(json dict, arrays dict, text): rbcstab simulate --json, the trajectory, the CLI's text; t_eval: the output "
        "grid (empty: the scene's); dense_output: arrays['dense'], a DenseOutput.");
  m.def("thresholds", &thresholds_scene, py::arg("scene"), py::arg("exact_C_star") = false,
        "(json dict, text): rbcstab thresholds [--exact-C-star] --json and its text.");
  m.def("post", &post_scene, py::arg("scene"), "(json dict, text): rbcstab post --json and its text.");
  m.def("_time_simulate_cpp", &time_simulate_cpp, py::arg("scene"), py::arg("repeats"),
        "Seconds per repeat of simulate's C++ work (truncation, run, JSON), for the overhead benchmark.");
  m.def("summary", &summary_scene, py::arg("scene"), "(json dict, text): rbcstab summary --json and its text.");
}

}  // namespace rbcstab::python
