// One scene's runs, as the CLI's simulate, thresholds, post and summary: the same library calls, the same JSON
// serialisers (so a Python dict equals json.loads of the CLI's --json), the GIL released while they compute.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <memory>

#include "bindings.hpp"
#include "rbcstab/analysis/analysis_io.hpp"
#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/io/simulation_io.hpp"
#include "rbcstab/verdict/certified_run.hpp"
#include "rbcstab/verdict/verdict_io.hpp"

namespace rbcstab::python {

namespace {

// Delta_l(t) as a (samples, L - 1) array, column l - 2 (the trajectory keeps one row per sample).
py::array_t<double> Delta_matrix(const Trajectory& tr, int L) {
  const py::ssize_t rows = py::ssize_t(tr.t.size()), cols = L - 1;
  py::array_t<double> out({rows, cols});
  auto a = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows; ++i)
    for (py::ssize_t j = 0; j < cols; ++j) a(i, j) = tr.Delta_l[std::size_t(i)][std::size_t(j)];
  return out;
}

// The scene with Ctrl-C wired into its integrator.
SceneFile interruptible(const py::handle& scene) {
  SceneFile f = scene_file(scene);
  f.options.integrator.poll = signal_poll();
  return f;
}

py::tuple simulate_file(const py::handle& scene) {
  SceneFile f = interruptible(scene);
  SimulationResult r;
  {
    py::gil_scoped_release release;
    r = simulate_scene(f, f.options);
  }
  const nlohmann::json j = simulation_json(f, r);
  py::dict arrays;
  arrays["Delta"] = Delta_matrix(r.trajectory, r.L);
  arrays["t"] = own(std::move(r.trajectory.t));
  arrays["sigma"] = own(std::move(r.trajectory.sigma));
  arrays["r"] = own(std::move(r.trajectory.r));
  arrays["Psi"] = own(std::move(r.trajectory.Psi));
  arrays["y_final"] = own(std::move(r.y_final));
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

}  // namespace

void bind_runs(py::module_& m) {
  m.def("simulate", &simulate_file, py::arg("scene"),
        "(json dict, arrays dict, text): rbcstab simulate --json, the trajectory, the CLI's text.");
  m.def("thresholds", &thresholds_scene, py::arg("scene"), py::arg("exact_C_star") = false,
        "(json dict, text): rbcstab thresholds [--exact-C-star] --json and its text.");
  m.def("post", &post_scene, py::arg("scene"), "(json dict, text): rbcstab post --json and its text.");
  m.def("_time_simulate_cpp", &time_simulate_cpp, py::arg("scene"), py::arg("repeats"),
        "Seconds per repeat of simulate's C++ work (truncation, run, JSON), for the overhead benchmark.");
  m.def("summary", &summary_scene, py::arg("scene"), "(json dict, text): rbcstab summary --json and its text.");
}

}  // namespace rbcstab::python
